#include "baudprobe.h"

#include "session/rotatorsession.h"
#include "transport/serialports.h"

#include <QUrl>
#include <QUrlQuery>

namespace slew::tuning {

using session::RotatorSession;

BaudProbe::BaudProbe(QObject *parent)
    : QObject(parent),
      m_attempt(this, 2000, [this] { conclude(false, tr("no answer in %1 s").arg(m_attempt.limitMs() / 1000.0)); })
{
}

BaudProbe::~BaudProbe() = default;

bool BaudProbe::isSerial(const QString &uri)
{
    return uri.trimmed().startsWith(QLatin1String("serial:"), Qt::CaseInsensitive);
}

QString BaudProbe::withBaud(const QString &uri, qint32 baud)
{
    const qsizetype q = uri.indexOf(u'?');
    const QString base = q < 0 ? uri : uri.left(q);
    QUrlQuery query(q < 0 ? QString() : uri.mid(q + 1));
    query.removeAllQueryItems(QStringLiteral("baud"));
    query.addQueryItem(QStringLiteral("baud"), QString::number(baud));
    return base + u'?' + query.toString();
}

bool BaudProbe::start(const QString &uri, protocol::Dialect dialect)
{
    m_error.clear();
    if (uri.trimmed().isEmpty()) {
        m_error = tr("enter a port or an address first");
        return false;
    }
    cancel();
    m_uri = uri.trimmed();
    m_dialect = dialect;
    m_results.clear();
    m_pending = isSerial(m_uri) ? transport::commonBaudRates() : QList<qint32>{0};
    m_total = int(m_pending.size());
    next();
    return true;
}

void BaudProbe::cancel()
{
    m_pending.clear();
    m_attempt.end();
}

QString BaudProbe::answeringUri() const
{
    for (const BaudResult &r : m_results) {
        if (r.answered)
            return r.uri;
    }
    return {};
}

void BaudProbe::next()
{
    if (m_pending.isEmpty()) {
        emit progress(100, tr("done"));
        emit finished(!answeringUri().isEmpty());
        return;
    }
    const qint32 baud = m_pending.takeFirst();
    BaudResult r;
    r.baud = baud;
    r.uri = baud > 0 ? withBaud(m_uri, baud) : m_uri;
    m_results.append(r);
    emit progress(100 * (m_total - int(m_pending.size()) - 1) / std::max(1, m_total),
                  baud > 0 ? tr("trying %1 baud").arg(baud) : tr("trying %1").arg(m_uri));

    RotatorSession *session = m_attempt.begin(m_dialect);
    connect(session, &RotatorSession::positionChanged, this, [this](double az, double el, bool stale) {
        if (!stale)
            conclude(true, tr("answered: azimuth %1°, elevation %2°").arg(az, 0, 'f', 2).arg(el, 0, 'f', 2));
    });
    connect(session, &RotatorSession::stateChanged, this, [this](RotatorSession::State s, const QString &detail) {
        if (s == RotatorSession::State::Disconnected)
            conclude(false, detail);
    });
    m_attempt.go(r.uri);
}

void BaudProbe::conclude(bool answered, const QString &detail)
{
    if (!m_attempt.isRunning() || m_results.isEmpty())
        return;
    m_attempt.end();
    m_results.back().answered = answered;
    m_results.back().detail = detail;
    emit tried(m_results.back());
    // Leave the event loop a turn so the port is closed before it reopens.
    QMetaObject::invokeMethod(this, &BaudProbe::next, Qt::QueuedConnection);
}

} // namespace slew::tuning
