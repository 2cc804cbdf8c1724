#include "baudprobe.h"

#include "session/rotatorsession.h"
#include "transport/serialports.h"

#include <QUrl>
#include <QUrlQuery>

namespace slew::tuning {

using session::RotatorSession;

BaudProbe::BaudProbe(QObject *parent) : QObject(parent)
{
    m_timer.setSingleShot(true);
    m_timer.setInterval(2000);
    connect(&m_timer, &QTimer::timeout, this,
            [this] { conclude(false, tr("no answer in %1 s").arg(m_timer.interval() / 1000.0)); });
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
    m_timer.stop();
    m_pending.clear();
    if (m_session) {
        m_session->disconnect(this);
        m_session.release()->deleteLater(); // we may be inside one of its signals
    }
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

    m_session = std::make_unique<RotatorSession>();
    model::RotatorProfile profile;
    profile.dialect = m_dialect;
    m_session->setProfile(profile);
    connect(m_session.get(), &RotatorSession::positionChanged, this, [this](double az, double el, bool stale) {
        if (!stale)
            conclude(true, tr("answered: azimuth %1°, elevation %2°").arg(az, 0, 'f', 2).arg(el, 0, 'f', 2));
    });
    connect(m_session.get(), &RotatorSession::stateChanged, this,
            [this](RotatorSession::State s, const QString &detail) {
                if (s == RotatorSession::State::Disconnected)
                    conclude(false, detail);
            });
    m_timer.start();
    m_session->connectTo(r.uri);
}

void BaudProbe::conclude(bool answered, const QString &detail)
{
    if (!m_session || m_results.isEmpty())
        return;
    m_timer.stop();
    m_session->disconnect(this);
    m_session->disconnectFromRotator();
    m_session.release()->deleteLater();
    m_results.back().answered = answered;
    m_results.back().detail = detail;
    emit tried(m_results.back());
    // Leave the event loop a turn so the port is closed before it reopens.
    QMetaObject::invokeMethod(this, &BaudProbe::next, Qt::QueuedConnection);
}

} // namespace slew::tuning
