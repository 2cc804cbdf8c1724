// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One HTTP(S) GET with limits: a cap on the bytes, a limit on silence and a
// limit on the whole transfer. A server that sends too much, too slowly or
// nothing at all is given up with a message that says which limit it hit,
// instead of Qt's "Operation canceled".
//
// The answer is read as it arrives into a buffer of this object's, and the
// reply's own buffer is kept small (QNetworkReply::setReadBufferSize), so
// memory stays within the cap however large the answer is, announced or
// chunked.

#include <QByteArray>
#include <QObject>
#include <QString>
#include <QTimer>
#include <QUrl>

class QNetworkAccessManager;
class QNetworkReply;

namespace slew::sky {

struct DownloadLimits {
    qint64 maxBytes = 0;
    int silenceMs = 0;  // no byte for this long: given up
    int transferMs = 0; // the whole transfer, however steadily it trickles
};

// "30 s", "120 s", "300 ms": a limit as the messages state it.
QString durationText(int ms);

class BoundedDownload : public QObject {
    Q_OBJECT
public:
    // Starts at once; emits done() exactly once, from the event loop.
    BoundedDownload(QNetworkAccessManager *network, const QUrl &url, const DownloadLimits &limits,
                    QObject *parent = nullptr);
    ~BoundedDownload() override;

signals:
    // The whole answer, or an empty body and why there is none ("no data
    // for 30 s", "larger than the 16 MiB limit", "the server answered 404
    // Not Found"). The error never names the URL: the caller knows it.
    void done(const QByteArray &body, const QString &error);

private:
    void readAvailable();
    void checkAnnouncedLength();
    void onFinished();
    void giveUp(const QString &why);
    void finish(QByteArray body, const QString &error); // by value: it may be m_body
    QString tooLarge() const;

    QNetworkReply *m_reply = nullptr;
    DownloadLimits m_limits;
    QByteArray m_body;
    QTimer m_silence;
    QTimer m_transfer;
    bool m_done = false;
};

} // namespace slew::sky
