// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundeddownload.h"

#include "input/boundedfile.h"

#include <QNetworkAccessManager>
#include <QNetworkReply>
#include <QNetworkRequest>

#include <algorithm>
#include <utility>

namespace slew::sky {
namespace {

// What the reply may hold before it is read into our buffer: enough for
// loopback speeds, small beside the cap.
constexpr qint64 kReplyBufferBytes = 256 * 1024;

} // namespace

QString durationText(int ms)
{
    if (ms >= 1000 && ms % 1000 == 0)
        return QStringLiteral("%1 s").arg(ms / 1000);
    return QStringLiteral("%1 ms").arg(ms);
}

BoundedDownload::BoundedDownload(QNetworkAccessManager *network, const QUrl &url, const DownloadLimits &limits,
                                 QObject *parent)
    : QObject(parent)
    , m_limits(limits)
{
    QNetworkRequest request(url);
    request.setAttribute(QNetworkRequest::RedirectPolicyAttribute, QNetworkRequest::NoLessSafeRedirectPolicy);
    // Qt's own transfer timeout would end in "Operation canceled"; the
    // timers below say which limit was hit.
    request.setTransferTimeout(0);
    m_reply = network->get(request);
    m_reply->setReadBufferSize(kReplyBufferBytes);

    // Precise: a coarse timer may fire a few per cent early, and the
    // message states the limit.
    m_silence.setTimerType(Qt::PreciseTimer);
    m_transfer.setTimerType(Qt::PreciseTimer);
    m_silence.setSingleShot(true);
    m_silence.setInterval(m_limits.silenceMs);
    m_transfer.setSingleShot(true);
    m_transfer.setInterval(m_limits.transferMs);
    connect(&m_silence, &QTimer::timeout, this,
            [this] { giveUp(QStringLiteral("no data for %1").arg(durationText(m_limits.silenceMs))); });
    connect(&m_transfer, &QTimer::timeout, this,
            [this] { giveUp(QStringLiteral("took longer than %1").arg(durationText(m_limits.transferMs))); });
    connect(m_reply, &QNetworkReply::metaDataChanged, this, &BoundedDownload::checkAnnouncedLength);
    connect(m_reply, &QNetworkReply::readyRead, this, &BoundedDownload::readAvailable);
    connect(m_reply, &QNetworkReply::finished, this, &BoundedDownload::onFinished);
    m_silence.start();
    m_transfer.start();
}

BoundedDownload::~BoundedDownload()
{
    if (m_reply) {
        m_reply->disconnect(this);
        m_reply->abort();
        m_reply->deleteLater();
    }
}

QString BoundedDownload::tooLarge() const
{
    return QStringLiteral("larger than the %1 limit").arg(input::byteSizeText(m_limits.maxBytes));
}

void BoundedDownload::checkAnnouncedLength()
{
    m_silence.start();
    // A redirect's own headers say nothing about the answer that follows.
    const int status = m_reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
    if (status >= 300 && status < 400)
        return;
    bool known = false;
    const qint64 announced = m_reply->header(QNetworkRequest::ContentLengthHeader).toLongLong(&known);
    if (known && announced > m_limits.maxBytes) {
        giveUp(tooLarge() + QStringLiteral(" (the server announces %1)").arg(input::byteSizeText(announced)));
        return;
    }
    if (known && announced > 0 && m_body.isEmpty())
        m_body.reserve(qsizetype(announced));
}

void BoundedDownload::readAvailable()
{
    if (m_done)
        return;
    m_silence.start();
    // Never more than one byte past the cap: that byte is proof enough.
    while (m_reply->bytesAvailable() > 0) {
        const qint64 room = m_limits.maxBytes + 1 - m_body.size();
        const QByteArray piece = m_reply->read(std::min(m_reply->bytesAvailable(), room));
        if (piece.isEmpty())
            break;
        m_body.append(piece);
        if (m_body.size() > m_limits.maxBytes) {
            giveUp(tooLarge());
            return;
        }
    }
}

void BoundedDownload::onFinished()
{
    if (m_done)
        return;
    readAvailable();
    if (m_done)
        return;
    const QNetworkReply::NetworkError error = m_reply->error();
    bool known = false;
    const qint64 announced = m_reply->header(QNetworkRequest::ContentLengthHeader).toLongLong(&known);
    // Qt takes a close before the announced length as the end of the
    // answer; it is a transfer cut short. (A compressed answer's length
    // counts the compressed bytes, so it cannot be compared.)
    const bool cutShort = known && !m_reply->hasRawHeader("Content-Encoding") && m_body.size() < announced;
    if (error == QNetworkReply::NoError && !cutShort) {
        finish(std::exchange(m_body, {}), QString());
        return;
    }
    const int status = m_reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
    if (status >= 400) {
        const QString reason = m_reply->attribute(QNetworkRequest::HttpReasonPhraseAttribute).toString();
        finish({}, QStringLiteral("the server answered %1 %2").arg(status).arg(reason).trimmed());
        return;
    }
    if (cutShort || (error == QNetworkReply::RemoteHostClosedError && !m_body.isEmpty())) {
        finish({}, known ? QStringLiteral("the server closed the connection after %1 of the %2 bytes it announced")
                               .arg(m_body.size())
                               .arg(announced)
                         : QStringLiteral("the server closed the connection after %1 bytes").arg(m_body.size()));
        return;
    }
    finish({}, m_reply->errorString());
}

void BoundedDownload::giveUp(const QString &why)
{
    if (m_done)
        return;
    finish({}, why);
}

void BoundedDownload::finish(QByteArray body, const QString &error)
{
    m_done = true;
    m_silence.stop();
    m_transfer.stop();
    m_body.clear();
    m_body.squeeze();
    // The reply goes now: aborting closes the connection, so a server still
    // sending stops being read.
    QNetworkReply *reply = m_reply;
    m_reply = nullptr;
    reply->disconnect(this);
    if (!reply->isFinished())
        reply->abort();
    reply->deleteLater();
    emit done(body, error);
}

} // namespace slew::sky
