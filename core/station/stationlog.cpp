// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationlog.h"

#include "alarmmonitor.h"
#include "dopplerradio.h"
#include "schedulerunner.h"
#include "passrecorder.h"
#include "station.h"

#include "bridge/rotctldserver.h"
#include "input/logtext.h"
#include "records/passrecordstore.h"
#include "session/rotatorsession.h"
#include "tracking/passrunner.h"

#include <QDateTime>

namespace slew::station {

using session::RotatorSession;

StationLog::StationLog(Station *station, std::FILE *file, QObject *parent)
    : QObject(parent), m_station(station), m_file(file)
{
    for (int i = 0; i < station->rotorCount(); ++i)
        followRotor(i);
    if (tracking::PassRunner *runner = station->passRunner())
        connect(runner, &tracking::PassRunner::logLine, this, [this](const QString &line) { write(tr("track: %1").arg(line)); });
    if (DopplerRadio *radio = station->radio())
        connect(radio, &DopplerRadio::logLine, this, &StationLog::write);
    if (ScheduleRunner *schedule = station->scheduleRunner())
        connect(schedule, &ScheduleRunner::logLine, this, &StationLog::write); // its lines say "schedule:"

    if (PassRecorder *recorder = station->passRecorder())
        connect(recorder, &PassRecorder::logLine, this, &StationLog::write);
    connect(station->passRecords(), &records::PassRecordStore::writeFailed, this,
            [this](const QString &error) { write(tr("records: %1").arg(error)); });
}

void StationLog::followRotor(int index)
{
    RotatorSession *s = m_station->session(index);
    // With several rotors every line says whose it is.
    const int number = m_station->rotorNumber(index);
    const QString who = number > 0 ? tr("rotor %1: ").arg(number) : QString();
    auto say = [this, who](const QString &line) { write(who + line); };
    connect(s, &RotatorSession::stateChanged, this, [say](RotatorSession::State, const QString &detail) {
        say(tr("link: %1").arg(detail));
    });
    // Lines about what the controller sent come escaped and rate-limited;
    // a controller alarm is among them ("controller alarm: ..."), so it is
    // not logged a second time from alarmReceived, which is not limited.
    // Every stop, with what asked for it (a rotctld client's S, MQTT, a
    // lease run out, the service ending on a signal).
    connect(s, &RotatorSession::stopSent, this, [say](const QString &cause) { say(tr("stop sent (%1)").arg(cause)); });
    connect(s, &RotatorSession::errorOccurred, this, [say](const QString &m) { say(tr("error: %1").arg(m)); });
    connect(s, &RotatorSession::commandRefused, this, [say](const QString &m) { say(tr("refused: %1").arg(m)); });
    connect(s, &RotatorSession::versionChanged, this, [say](const QString &v) { say(tr("controller: %1").arg(v)); });
    connect(s, &RotatorSession::targetChanged, this, [this, index, say](double az, double el) {
        // A tracked pass sends a target every second or two: its plan and
        // figures are logged instead.
        if (index == 0 && m_station->passRunner() && m_station->passRunner()->holdsRotator())
            return;
        say(tr("target: az %1 el %2").arg(az, 0, 'f', 1).arg(el, 0, 'f', 1));
    });
    connect(s, &RotatorSession::errorFlagsChanged, this, [say](int flags) {
        const QString text = session::describeErrorFlags(flags);
        say(tr("error register: %1").arg(text.isEmpty() ? tr("no error") : text));
    });
    // The alarm monitor's judgements, in the words of the window's banner.
    // A lost link and a refused move have their own lines above ("link:",
    // "refused:"), so they are not said twice.
    auto saidAbove = [](const QString &key) { return key == u"link" || key == u"refused-move"; };
    AlarmMonitor *alarms = m_station->alarms(index);
    connect(alarms, &AlarmMonitor::alarmRaised, this,
            [say, saidAbove](const QString &key, const QString &text, AlarmMonitor::Severity severity) {
                if (!saidAbove(key))
                    say((severity == AlarmMonitor::Severity::Alarm ? tr("alarm: %1") : tr("warning: %1")).arg(text));
            });
    connect(alarms, &AlarmMonitor::alarmCleared, this, [say, saidAbove](const QString &key, const QString &text) {
        if (!saidAbove(key))
            say(tr("cleared: %1").arg(text));
    });
    connect(m_station->server(index), &bridge::RotctldServer::logMessage, this, say);
}

void StationLog::write(const QString &line)
{
    // Device and client text reaches here too: no control characters (an
    // escape sequence would reach the operator's terminal), no endless lines.
    const QString stamped =
        QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs) + QLatin1Char(' ') + input::loggableText(line);
    std::fprintf(m_file, "%s\n", qPrintable(stamped));
    std::fflush(m_file);
}

} // namespace slew::station
