// SPDX-License-Identifier: GPL-3.0-or-later
#include "passrecorder.h"

#include "dopplerradio.h"

#include "records/passrecordstore.h"
#include "session/rotatorsession.h"
#include "sky/passes.h"
#include "sky/utctime.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"
#include "tracking/tracktarget.h"

#include <cmath>

namespace slew::station {

using records::Outcome;
using tracking::Tracker;

PassRecorder::PassRecorder(session::RotatorSession *session, tracking::PassRunner *runner, DopplerRadio *radio,
                           const tracking::StationClock *clock, QObject *parent)
    : QObject(parent), m_session(session), m_runner(runner), m_radio(radio), m_clock(clock)
{
    const Tracker *tracker = &runner->tracker();
    connect(tracker, &Tracker::stateChanged, this, &PassRecorder::onTrackerState);
    connect(tracker, &Tracker::pointingError, this, &PassRecorder::onPointingError);
    if (m_radio) {
        connect(m_radio, &DopplerRadio::steeringChanged, this, [this](bool steering) {
            if (steering && m_id)
                m_radioSteered = true;
        });
    }
}

PassRecorder::~PassRecorder()
{
    if (m_id)
        finish(Outcome::Interrupted, tr("the station was closed"));
}

void PassRecorder::setStore(records::PassRecordStore *store)
{
    m_store = store;
}

records::PassPlanned PassRecorder::planned(const tracking::TrackTarget &target, const sky::Pass &pass, bool rehearsal)
{
    records::PassPlanned p;
    p.target = target.name();
    if (target.kind == tracking::TrackTarget::Kind::Satellite && target.elements.catalogueNumber > 0)
        p.norad = target.elements.catalogueNumber;
    p.aos = sky::utcFromJulian(pass.aos.julian);
    p.tca = sky::utcFromJulian(pass.tca.julian);
    p.los = sky::utcFromJulian(pass.los.julian);
    p.maxElevationDeg = pass.maxElevationDeg();
    p.rehearsal = rehearsal;
    return p;
}

std::optional<qint64> PassRecorder::recordDropped(const tracking::TrackTarget &target, const sky::Pass &pass,
                                                  const QString &reason, QString *error)
{
    if (!m_store || !m_store->canRecord()) {
        if (error)
            *error = tr("no pass records are open");
        return std::nullopt;
    }
    const auto id = m_store->recordDropped(planned(target, pass, m_clock->isRehearsal()), reason, error);
    if (id)
        emit logLine(tr("records: pass %1 (%2) dropped: %3").arg(*id).arg(target.name(), reason));
    return id;
}

qint64 PassRecorder::nowMs() const
{
    return sky::utcFromJulian(m_clock->nowJulian()).toMSecsSinceEpoch();
}

void PassRecorder::onTrackerState(Tracker::State state, const QString &why)
{
    switch (state) {
    case Tracker::State::Tracking:
        if (!m_id)
            begin();
        break;
    case Tracker::State::Done:
        if (m_id)
            finish(Outcome::Tracked, {});
        break;
    case Tracker::State::Idle:
    case Tracker::State::Waiting:
        // Ended before LOS: stopped, untracked, the link lost, the clock
        // changed, the station closing.
        if (m_id)
            finish(Outcome::Interrupted, why);
        break;
    }
}

void PassRecorder::begin()
{
    if (!m_store || !m_store->canRecord() || !m_runner->pass())
        return;
    const tracking::TrackTarget &target = m_runner->target();
    records::PassPlanned p = planned(target, *m_runner->pass(), m_clock->isRehearsal());
    p.plannedWorstDeg = m_runner->tracker().plan().predictedWorstDeg;
    QString error;
    m_id = m_store->beginPass(p, &error);
    if (!m_id) {
        emit logLine(tr("records: %1").arg(error));
        return;
    }
    m_recordingIn = m_store;
    m_target = p.target;
    m_lastSampleMs = 0;
    m_samples = 0;
    m_radioSteered = m_radio && m_radio->isSteering();
    m_rehearsal = p.rehearsal;
    emit logLine(tr("records: pass %1 (%2) in progress%3").arg(*m_id).arg(m_target, rehearsalMark()));
    emit recording(*m_id, true);
}

records::PassFigures PassRecorder::figures() const
{
    records::PassFigures f;
    const tracking::TrackingFigures &t = m_runner->tracker().figures();
    // Before the settling time there are no figures, not zeros.
    if (t.samples > 0) {
        f.rmsDeg = t.rmsDeg;
        f.worstDeg = t.worstDeg;
    }
    f.commands = t.commands;
    if (m_radioSteered && m_radio) {
        const radio::DopplerFigures d = m_radio->figures();
        if (d.samples > 0) {
            f.dopplerRmsHz = d.rmsHz;
            f.dopplerWorstHz = d.worstHz;
        }
    }
    return f;
}

void PassRecorder::onPointingError(double degrees, double)
{
    if (!m_id || !m_session->hasPosition())
        return;
    const qint64 now = nowMs();
    if (m_samples > 0 && now - m_lastSampleMs < kSampleSpacingMs)
        return;
    const tracking::SkyPoint target = m_runner->tracker().targetNow();
    m_recordingIn->addSample(*m_id, records::PassSample{now, m_session->azimuth(), m_session->elevation(),
                                                        target.azimuthDeg, target.elevationDeg, degrees});
    m_recordingIn->setFigures(*m_id, figures());
    m_lastSampleMs = now;
    ++m_samples;
}

QString PassRecorder::rehearsalMark() const
{
    // Said where the record is, so a rehearsed pass is not read in the
    // log as one of the real sky.
    return m_rehearsal ? tr(" (rehearsal)") : QString();
}

void PassRecorder::finish(Outcome outcome, const QString &why)
{
    const qint64 id = *m_id;
    m_id.reset();
    m_recordingIn->setFigures(id, figures());
    QString error;
    if (!m_recordingIn->finishPass(id, outcome, why, sky::utcFromJulian(m_clock->nowJulian()), &error))
        emit logLine(tr("records: %1").arg(error));
    else
        emit logLine(tr("records: pass %1 (%2) %3%4, %5 samples%6")
                         .arg(id)
                         .arg(m_target, records::outcomeName(outcome),
                              why.isEmpty() ? QString() : QStringLiteral(": ") + why)
                         .arg(m_samples)
                         .arg(rehearsalMark()));
    m_recordingIn = nullptr;
    emit recording(id, false);
}

} // namespace slew::station
