// SPDX-License-Identifier: GPL-3.0-or-later
#include "headlessstation.h"

#include "input/finitenumber.h"

#include "input/logtext.h"
#include "rotctldserver.h"
#include "protocol/dialect.h"
#include "session/rotatorsession.h"
#include "session/stopbeforeexit.h"
#include "transport/linkfactory.h"
#include "transport/sharedline.h"

#include <QDateTime>

namespace slew::bridge {

using session::RotatorSession;

std::optional<QList<int>> parseRotorList(const QString &text, QString *error)
{
    QList<int> rotors;
    auto add = [&](int n) {
        if (n < 1 || n > 4) {
            *error = QObject::tr("rotors are 1 to 4, not %1").arg(n);
            return false;
        }
        if (rotors.contains(n)) {
            *error = QObject::tr("rotor %1 is named twice").arg(n);
            return false;
        }
        rotors.append(n);
        return true;
    };
    for (const QString &item : text.split(u',')) {
        const QStringList range = item.trimmed().split(u'-');
        bool okFirst = false, okLast = false;
        const int first = range.front().trimmed().toInt(&okFirst);
        const int last = range.size() == 2 ? range.back().trimmed().toInt(&okLast) : first;
        if (range.size() > 2 || !okFirst || (range.size() == 2 && !okLast) || last < first) {
            *error = QObject::tr("'%1' is not a rotor or a range of rotors (as in 1,2,4 or 1-4)").arg(item.trimmed());
            return std::nullopt;
        }
        for (int n = first; n <= last; ++n) {
            if (!add(n))
                return std::nullopt;
        }
    }
    return rotors;
}

std::optional<model::RotatorLimits> parseLimits(const QString &text, QString *error)
{
    const QStringList axes = text.split(u',');
    auto range = [](const QString &part, double *low, double *high) {
        const QStringList ends = part.split(u':');
        if (ends.size() != 2)
            return false;
        const std::optional<double> a = input::finiteNumber(ends[0]), b = input::finiteNumber(ends[1]);
        if (!a || !b)
            return false;
        *low = *a;
        *high = *b;
        return true;
    };
    model::RotatorLimits limits;
    if (axes.size() != 2 || !range(axes[0], &limits.azMin, &limits.azMax) || !range(axes[1], &limits.elMin, &limits.elMax)) {
        *error = QObject::tr("expected AZMIN:AZMAX,ELMIN:ELMAX, as 0:450,0:180");
        return std::nullopt;
    }
    if (const QString why = limits.validate(); !why.isEmpty()) {
        *error = why;
        return std::nullopt;
    }
    return limits;
}

HeadlessStation::HeadlessStation(std::FILE *logFile, QObject *parent) : QObject(parent), m_log(logFile) {}

HeadlessStation::Rotor &HeadlessStation::addRotor(int number, const model::RotatorProfile &profile)
{
    Rotor &rotor = m_rotors.emplace_back();
    rotor.number = number;
    rotor.session = std::make_unique<RotatorSession>();
    RotatorSession *s = rotor.session.get();
    RotatorSession::Options options = s->options();
    options.autoReconnect = true; // a service keeps trying after a loss
    s->setOptions(options);
    s->setProfile(profile);
    if (m_line)
        s->setLinkMaker([line = m_line.get()](const QString &uri) { return line->makeLink(uri); });

    // With several rotors every line says whose it is.
    const QString who = number > 0 ? tr("rotor %1: ").arg(number) : QString();
    auto say = [this, who](const QString &line) { log(who + line); };
    connect(s, &RotatorSession::stateChanged, this, [say](RotatorSession::State, const QString &detail) {
        say(tr("link: %1").arg(detail));
    });
    // Lines about what the controller sent come escaped and rate-limited;
    // a controller alarm is among them ("controller alarm: ..."), so it is
    // not logged a second time from alarmReceived, which is not limited.
    connect(s, &RotatorSession::errorOccurred, this, [say](const QString &m) { say(tr("error: %1").arg(m)); });
    connect(s, &RotatorSession::unreadableRepliesAlarm, this, [say](bool on, const QString &text) {
        say(on ? tr("alarm: %1").arg(text) : tr("cleared: the controller's replies are readable again"));
    });
    connect(s, &RotatorSession::commandRefused, this, [say](const QString &m) { say(tr("refused: %1").arg(m)); });
    connect(s, &RotatorSession::versionChanged, this, [say](const QString &v) { say(tr("controller: %1").arg(v)); });
    connect(s, &RotatorSession::targetChanged, this, [this, say](double az, double el) {
        // A tracked pass sends a target every second or two: its plan and
        // figures are logged instead.
        if (m_runner && m_runner->holdsRotator())
            return;
        say(tr("target: az %1 el %2").arg(az, 0, 'f', 1).arg(el, 0, 'f', 1));
    });
    connect(s, &RotatorSession::errorFlagsChanged, this, [say](int flags) {
        const QString text = session::describeErrorFlags(flags);
        say(tr("error register: %1").arg(text.isEmpty() ? tr("no error") : text));
    });
    return rotor;
}

bool HeadlessStation::listen(Rotor &rotor, const HeadlessConfig &config, quint16 port, QString *error)
{
    rotor.server = std::make_unique<RotctldServer>(rotor.session.get());
    RotctldServer *server = rotor.server.get();
    server->setAllowedClients(config.allowedClients);
    server->setMaxClients(config.rotctldMaxClients);
    server->setDeadband(config.profile.deadbandDeg);
    const QString who = rotor.number > 0 ? tr("rotor %1: ").arg(rotor.number) : QString();
    connect(server, &RotctldServer::logMessage, this, [this, who](const QString &m) { log(who + m); });
    server->setLogCommands(true); // polls excepted, escaped and rate-limited per client
    if (!server->listen(config.rotctldAddress, port, error)) {
        if (rotor.number > 0)
            *error = who + *error;
        return false;
    }
    // The ready line scripts wait for, with the real port.
    log(who + tr("rotctld listening on %1:%2").arg(server->address().toString()).arg(server->port()));
    return true;
}

HeadlessStation::~HeadlessStation() = default;

void HeadlessStation::log(const QString &line)
{
    // Device and client text reaches here too: no control characters (an
    // escape sequence would reach the operator's terminal), no endless lines.
    const QString stamped =
        QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs) + QLatin1Char(' ') + input::loggableText(line);
    std::fprintf(m_log, "%s\n", qPrintable(stamped));
    std::fflush(m_log);
}

bool HeadlessStation::start(const HeadlessConfig &config, QString *error)
{
    if (config.station)
        log(tr("station: %1").arg(sky::describeStation(*config.station)));
    model::RotatorProfile profile = config.profile;
    // A rotctld:// peer speaks one dialect whatever the profile names (the
    // window takes it from the link's hints the same way).
    if (transport::linkHintsFor(profile.uri).dialect == protocol::dialectName(protocol::Dialect::Rotctld))
        profile.dialect = protocol::Dialect::Rotctld;

    QList<int> numbers = config.rotors;
    if (!numbers.isEmpty()) {
        if (config.rotctldEnabled && config.rotctldPort != 0 && int(config.rotctldPort) + numbers.size() - 1 > 65535) {
            *error = tr("--rotors: %1 ports from %2 run past 65535").arg(numbers.size()).arg(config.rotctldPort);
            return false;
        }
        m_line = std::make_unique<transport::SharedLine>(profile.uri);
        if (!m_line->isValid()) {
            *error = m_line->error();
            return false;
        }
    } else {
        numbers = {0};
    }
    for (int n : numbers)
        addRotor(n, profile);

    if (config.rotctldEnabled) {
        for (size_t i = 0; i < m_rotors.size(); ++i) {
            const quint16 port = config.rotctldPort == 0 ? 0 : quint16(config.rotctldPort + i);
            if (!listen(m_rotors[i], config, port, error))
                return false;
        }
    }
    if (config.track) {
        if (!config.station) {
            *error = tr("--track needs the station (--qth)");
            return false;
        }
        m_clock = std::make_unique<tracking::StationClock>(config.track->clockStartJulian, config.track->clockRate);
        m_runner = std::make_unique<tracking::PassRunner>(m_rotors.front().session.get());
        connect(m_runner.get(), &tracking::PassRunner::logLine, this, [this](const QString &line) { log(tr("track: %1").arg(line)); });
        // While Slew tracks, trackers on the rotctld port are held off.
        connect(m_runner.get(), &tracking::PassRunner::activeChanged, this, [this](bool active) {
            if (RotctldServer *server = m_rotors.front().server.get())
                active ? server->holdRemote(tr("Slew's own tracking")) : server->releaseRemote();
        });
        m_runner->setOtherSteering([this] {
            RotctldServer *server = m_rotors.front().server.get();
            const QString peer = server ? server->remoteSteering() : QString();
            return peer.isEmpty() ? peer : tr("remote tracker %1").arg(peer);
        });
        m_runner->start(config.track->target, *config.station, config.track->minElevationDeg, m_clock.get());
    }
    for (Rotor &rotor : m_rotors) {
        const QString uri = m_line ? transport::SharedLine::rotorUri(m_line->uri(), rotor.number) : profile.uri;
        log((rotor.number > 0 ? tr("rotor %1: ").arg(rotor.number) : QString()) + tr("connecting to %1").arg(uri));
        rotor.session->connectTo(uri);
    }
    return true;
}

void HeadlessStation::shutdown(const QString &why)
{
    if (m_stopping)
        return;
    m_stopping = true;
    log(tr("stopping: %1").arg(why));
    if (m_runner)
        m_runner->stop(why);
    for (Rotor &rotor : m_rotors) {
        if (rotor.server)
            rotor.server->close();
    }
    // Every rotor stops; the service ends once every stop has left the link.
    m_stillStopping = int(m_rotors.size());
    if (m_stillStopping == 0) {
        emit finished();
        return;
    }
    for (Rotor &rotor : m_rotors) {
        const QString who = rotor.number > 0 ? tr("rotor %1: ").arg(rotor.number) : QString();
        rotor.session->reportHeldBack(); // the journal gets the count of what it was spared
        if (session::stopThenCall(*rotor.session, this, [this] {
                if (--m_stillStopping == 0)
                    emit finished();
            }))
            log(who + tr("rotator stopped"));
    }
}

} // namespace slew::bridge
