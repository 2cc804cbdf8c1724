// SPDX-License-Identifier: GPL-3.0-or-later
#include "headlessstation.h"

#include "logtext.h"
#include "rotctldserver.h"
#include "protocol/dialect.h"
#include "session/rotatorsession.h"
#include "session/stopbeforeexit.h"
#include "transport/linkfactory.h"

#include <QDateTime>

namespace slew::bridge {

using session::RotatorSession;

HeadlessStation::HeadlessStation(std::FILE *logFile, QObject *parent)
    : QObject(parent), m_log(logFile), m_session(std::make_unique<RotatorSession>())
{
    RotatorSession *s = m_session.get();
    connect(s, &RotatorSession::stateChanged, this, [this](RotatorSession::State, const QString &detail) {
        log(tr("link: %1").arg(detail));
    });
    connect(s, &RotatorSession::errorOccurred, this, [this](const QString &m) { log(tr("error: %1").arg(m)); });
    connect(s, &RotatorSession::commandRefused, this, [this](const QString &m) { log(tr("refused: %1").arg(m)); });
    connect(s, &RotatorSession::alarmReceived, this, [this](const QString &m) { log(tr("alarm: %1").arg(m)); });
    connect(s, &RotatorSession::versionChanged, this, [this](const QString &v) { log(tr("controller: %1").arg(v)); });
    connect(s, &RotatorSession::targetChanged, this, [this](double az, double el) {
        log(tr("target: az %1 el %2").arg(az, 0, 'f', 1).arg(el, 0, 'f', 1));
    });
    connect(s, &RotatorSession::errorFlagsChanged, this, [this](int flags) {
        const QString text = session::describeErrorFlags(flags);
        log(tr("error register: %1").arg(text.isEmpty() ? tr("no error") : text));
    });
}

HeadlessStation::~HeadlessStation() = default;

void HeadlessStation::log(const QString &line)
{
    // Device and client text reaches here too: no control characters (an
    // escape sequence would reach the operator's terminal), no endless lines.
    const QString stamped =
        QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs) + QLatin1Char(' ') + loggableText(line);
    std::fprintf(m_log, "%s\n", qPrintable(stamped));
    std::fflush(m_log);
}

bool HeadlessStation::start(const HeadlessConfig &config, QString *error)
{
    if (config.station)
        log(tr("station: %1").arg(sky::describeStation(*config.station)));
    RotatorSession::Options options = m_session->options();
    options.autoReconnect = true; // a service keeps trying after a loss
    m_session->setOptions(options);
    model::RotatorProfile profile = config.profile;
    // A rotctld:// peer speaks one dialect whatever the profile names (the
    // window takes it from the link's hints the same way).
    if (transport::linkHintsFor(profile.uri).dialect == protocol::dialectName(protocol::Dialect::Rotctld))
        profile.dialect = protocol::Dialect::Rotctld;
    m_session->setProfile(profile);
    if (config.rotctldEnabled) {
        m_server = std::make_unique<RotctldServer>(m_session.get());
        m_server->setAllowedClients(config.allowedClients);
        m_server->setMaxClients(config.rotctldMaxClients);
        m_server->setDeadband(config.profile.deadbandDeg);
        connect(m_server.get(), &RotctldServer::logMessage, this, [this](const QString &m) { log(m); });
        m_server->setLogCommands(true); // polls excepted, escaped and rate-limited per client
        if (!m_server->listen(config.rotctldAddress, config.rotctldPort, error))
            return false;
        // The ready line scripts wait for, with the real port.
        log(tr("rotctld listening on %1:%2").arg(m_server->address().toString()).arg(m_server->port()));
    }
    log(tr("connecting to %1").arg(config.profile.uri));
    m_session->connectTo(config.profile.uri);
    return true;
}

void HeadlessStation::shutdown(const QString &why)
{
    if (m_stopping)
        return;
    m_stopping = true;
    log(tr("stopping: %1").arg(why));
    if (m_server)
        m_server->close();
    if (session::stopThenCall(*m_session, this, [this] { emit finished(); }))
        log(tr("rotator stopped"));
}

} // namespace slew::bridge
