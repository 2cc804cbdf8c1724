// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationservice.h"

#include "dopplerradio.h"
#include "schedulerunner.h"
#include "remoteoperation.h"
#include "station.h"
#include "stationlog.h"

#include "bridge/rotctldserver.h"
#include "radio/transpondersources.h"
#include "records/passrecordschema.h"
#include "records/passrecordstore.h"
#include "session/rotatorsession.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <QFileInfo>

namespace slew::station {

StationService::StationService(std::FILE *logFile, QObject *parent) : QObject(parent), m_logFile(logFile) {}

StationService::~StationService() = default;

session::RotatorSession *StationService::session() const
{
    return m_station ? m_station->session() : nullptr;
}

bridge::RotctldServer *StationService::server() const
{
    return m_station && m_station->server() && m_station->server()->isListening() ? m_station->server() : nullptr;
}

tracking::PassRunner *StationService::passRunner() const
{
    return m_station && m_tracking ? m_station->passRunner() : nullptr;
}

int StationService::rotorCount() const
{
    return m_station ? m_station->rotorCount() : 0;
}

bool StationService::listen(int index, const ServiceConfig &config, quint16 port, QString *error)
{
    bridge::RotctldServer *server = m_station->server(index);
    server->setAllowedClients(config.allowedClients);
    server->setMaxClients(config.rotctldMaxClients);
    server->setDeadband(config.profile.deadbandDeg);
    server->setLogCommands(true); // polls excepted, escaped and rate-limited per client
    const int number = m_station->rotorNumber(index);
    const QString who = number > 0 ? tr("rotor %1: ").arg(number) : QString();
    if (!server->listen(config.rotctldAddress, port, error)) {
        if (number > 0)
            *error = who + *error;
        return false;
    }
    // The ready line scripts wait for, with the real port.
    m_log->write(who + tr("rotctld listening on %1:%2").arg(server->address().toString()).arg(server->port()));
    return true;
}

bool StationService::start(const ServiceConfig &config, QString *error)
{
    StationOptions options;
    options.autoReconnect = true; // a service keeps trying after a loss
    options.profile = config.profile;
    options.rotors = config.rotors;
    options.sharedLineUri = config.profile.uri;
    if (config.rotctldEnabled && !config.rotors.isEmpty() && config.rotctldPort != 0
        && int(config.rotctldPort) + config.rotors.size() - 1 > 65535) {
        *error = tr("--rotors: %1 ports from %2 run past 65535").arg(config.rotors.size()).arg(config.rotctldPort);
        return false;
    }
    m_station = std::make_unique<Station>(options);
    if (!m_station->isValid()) {
        *error = m_station->error();
        return false;
    }
    m_log = std::make_unique<StationLog>(m_station.get(), m_logFile);
    connect(m_station.get(), &Station::shutDown, this, &StationService::finished);
    if (!openPassRecords(config, error))
        return false;
    if (config.station) {
        m_log->write(tr("station: %1").arg(sky::describeSite(*config.station)));
        if (config.station->horizon)
            m_log->write(tr("station: horizon mask: %1").arg(config.station->horizon->describe()));
        m_station->setPlace(config.station);
    }

    if (config.rotctldEnabled) {
        for (int i = 0; i < m_station->rotorCount(); ++i) {
            const quint16 port = config.rotctldPort == 0 ? 0 : quint16(config.rotctldPort + i);
            if (!listen(i, config, port, error))
                return false;
        }
    }
    if (config.track) {
        if (!config.station) {
            *error = tr("--track needs the station (--qth)");
            return false;
        }
        if (config.track->clockStartJulian)
            m_station->clock()->rehearse(*config.track->clockStartJulian, config.track->clockRate);
        m_tracking = true;
        m_station->setElementAgeLimitDays(config.track->maxElementAgeDays);
        QString refused;
        if (config.track->targets.size() == 1) {
            refused = m_station->track(config.track->target(), config.track->minElevationDeg).reason();
        } else {
            ScheduleOptions schedule;
            schedule.minElevationDeg = config.track->minElevationDeg;
            schedule.guardSeconds = config.track->guardSeconds;
            refused = m_station->runSchedule(config.track->targets, schedule).reason();
        }
        if (!refused.isEmpty()) {
            *error = refused;
            return false;
        }
    }
    if (config.radio && !startRadio(config, error))
        return false;
    for (int i = 0; i < m_station->rotorCount(); ++i) {
        const int number = m_station->rotorNumber(i);
        m_log->write((number > 0 ? tr("rotor %1: ").arg(number) : QString())
                     + tr("connecting to %1").arg(m_station->rotorUri(i)));
    }
    m_station->connectRotators();
    if (config.remote) {
        if (!m_station->startRemote(*config.remote, error)) {
            *error = tr("--mqtt: %1").arg(*error);
            return false;
        }
        connect(m_station->remote(), &RemoteOperation::logLine, m_log.get(), [this](const QString &line) { m_log->write(line); });
        m_log->write(tr("remote: connecting to %1 as station %2")
                         .arg(config.remote->broker.display(), config.remote->stationName));
    }
    return true;
}

bool StationService::startRadio(const ServiceConfig &config, QString *error)
{
    if (!config.track || config.track->targets.size() != 1
        || config.track->target().kind != tracking::TrackTarget::Kind::Satellite) {
        *error = tr("--radio goes with one --track of a satellite: Doppler is a satellite's");
        return false;
    }
    const int norad = config.track->target().elements.catalogueNumber;
    RadioOptions options = *config.radio;
    if (!options.downlinkHz && options.transponderFiles.isEmpty()) {
        // Neither given: the transponders `slew --update-transponders` cached.
        for (const QUrl &url : radio::savedTransponderUrls()) {
            const QString file = m_station->transponders()->cacheFile(url);
            if (QFileInfo::exists(file))
                options.transponderFiles << file;
        }
        if (options.transponderFiles.isEmpty()) {
            *error = tr("--radio needs its frequencies: --downlink (and --uplink), --transponders FILE, or "
                        "transponders cached by slew --update-transponders");
            return false;
        }
    }
    QStringList notes;
    const std::optional<radio::RadioPlan> plan = resolveRadioPlan(options, norad, &notes, error);
    if (!plan)
        return false;
    DopplerRadio *radio = m_station->radio();
    QString why = radio->setVfoLayout(config.radio->vfos);
    if (!why.isEmpty() || !radio->setLink(config.radio->uri, &why)) {
        *error = tr("--radio: %1").arg(why);
        return false;
    }
    for (const QString &note : std::as_const(notes))
        m_log->write(tr("radio: %1").arg(note));
    radio->setRestoreAfterPass(config.radio->restoreAfterPass);
    radio->setPlan(plan);
    m_log->write(tr("radio: connecting to %1").arg(radio->linkUri()));
    radio->connectRadio();
    return true;
}

bool StationService::openPassRecords(const ServiceConfig &config, QString *error)
{
    if (const QString problem = m_station->openPassRecords(config.passRecords, config.passKeepDays);
        !problem.isEmpty()) {
        // A file the operator named is a setting; the default one is not
        // worth a station that does not track.
        if (!config.passRecords.isEmpty()) {
            *error = tr("pass records: %1").arg(problem);
            return false;
        }
        m_log->write(tr("records: %1; passes are not recorded").arg(problem));
        return true;
    }
    const records::PassRecordStore *store = m_station->passRecords();
    const records::PassRecordStore::OpenNotes &notes = store->openNotes();
    m_log->write(tr("records: passes recorded in %1%2 (samples kept %3 days)")
                     .arg(store->path(), notes.created ? tr(", a new file") : QString())
                     .arg(store->keepDays()));
    if (notes.migratedFrom > 0)
        m_log->write(tr("records: %1 brought from schema version %2 to %3")
                         .arg(store->path())
                         .arg(notes.migratedFrom)
                         .arg(records::schema::kCurrentVersion));
    auto passes = [](int n) { return n == 1 ? tr("1 pass") : tr("%1 passes").arg(n); };
    if (notes.interrupted > 0)
        m_log->write(tr("records: %1 left in progress by a Slew that stopped, marked interrupted")
                         .arg(passes(notes.interrupted)));
    if (notes.prunedPasses > 0)
        m_log->write(tr("records: the samples of %1 recorded over %2 days ago removed")
                         .arg(passes(notes.prunedPasses))
                         .arg(store->keepDays()));
    return true;
}

void StationService::shutdown(const QString &why)
{
    if (!m_station || m_station->isShuttingDown())
        return;
    m_log->write(tr("stopping: %1").arg(why));
    m_station->shutdown(why);
}

} // namespace slew::station
