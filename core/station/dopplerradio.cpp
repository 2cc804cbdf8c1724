// SPDX-License-Identifier: GPL-3.0-or-later
#include "dopplerradio.h"

#include "radio/controllerradio.h"
#include "radio/frequencytext.h"
#include "radio/radiolinks.h"
#include "session/rotatorsession.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"
#include "tracking/tracktarget.h"

#include <array>
#include <cmath>
#include <limits>

namespace slew::station {

using radio::RadioLink;
using tracking::Tracker;

namespace {

// A lost radio is tried again after these many seconds, then every last one.
constexpr std::array kReopenSeconds{1, 2, 5, 10, 30};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The larger of two errors, either of which may be NaN (not measured).
double larger(double held, double error)
{
    if (!std::isfinite(error))
        return held;
    return !std::isfinite(held) || std::abs(error) > std::abs(held) ? error : held;
}

} // namespace

DopplerRadio::DopplerRadio(session::RotatorSession *session, tracking::PassRunner *runner,
                           const tracking::StationClock *clock, QObject *parent)
    : QObject(parent), m_session(session), m_runner(runner), m_clock(clock), m_worstReceive(kNaN),
      m_worstTransmit(kNaN)
{
    m_reopen.setSingleShot(true);
    connect(&m_reopen, &QTimer::timeout, this, [this] {
        if (m_wanted && m_link && m_link->state() == RadioLink::State::Closed)
            m_link->open();
    });
    connect(&m_runner->tracker(), &Tracker::stateChanged, this, &DopplerRadio::onPassState);
    // The controller's radio rides on the rotator's link: it comes back with it.
    connect(m_session, &session::RotatorSession::stateChanged, this, [this] {
        if (m_wanted && m_link && isControllers() && m_session->isConnected()
            && m_link->state() == RadioLink::State::Closed)
            m_link->open();
    });
}

DopplerRadio::~DopplerRadio()
{
    // The steering speaks to the link: it goes first.
    m_steering.reset();
}

bool DopplerRadio::setLink(const QString &uri, QString *error)
{
    std::unique_ptr<RadioLink> link;
    if (uri.trimmed() == QLatin1String(kControllerUri)) {
        link = std::make_unique<radio::ControllerRadioLink>(m_session);
    } else if (!uri.trimmed().isEmpty()) {
        QString why;
        link = radio::makeRadioLink(uri, &why);
        if (!link) {
            if (error)
                *error = why;
            return false;
        }
    }
    if (link) {
        if (const QString why = link->setVfoLayout(m_layout); !why.isEmpty()) {
            if (error)
                *error = why;
            return false;
        }
    }
    if (isSteering())
        end(tr("the radio was changed"));
    m_reopen.stop();
    m_reopenAttempt = 0;
    m_steering.reset();
    if (m_link)
        m_link->close();
    m_link = std::move(link);
    m_foundReceiveHz.reset();
    m_frequencies = {};
    emit linkChanged();
    emit frequenciesChanged();
    if (!m_link)
        return true;
    m_steering = std::make_unique<radio::DopplerSteering>(m_link.get());
    connect(m_steering.get(), &radio::DopplerSteering::measured, this, &DopplerRadio::onMeasured);
    connect(m_steering.get(), &radio::DopplerSteering::dialFollowed, this, [this](double offsetHz) {
        emit logLine(
            tr("radio: the operator's dial moved the downlink by %1; followed").arg(radio::signedHertz(offsetHz)));
    });
    connect(m_link.get(), &RadioLink::stateChanged, this, &DopplerRadio::onLinkState);
    connect(m_steering.get(), &radio::DopplerSteering::tuned, this,
            [this](const radio::RadioTuning &t) { noteFrequencies(t.receiveHz, t.transmitHz); });
    connect(m_link.get(), &RadioLink::frequenciesRead, this,
            [this](const radio::RadioFrequencies &f) { noteFrequencies(f.receiveHz, f.transmitHz); });
    connect(m_link.get(), &RadioLink::frequenciesRead, this, [this](const radio::RadioFrequencies &f) {
        // What the radio was on before Slew tuned it, to put back after
        // LOS: the answer to readFound()'s read. A pass waits for it (see
        // begin()): the steering would take it for the operator's dial.
        if (!m_readingFound)
            return;
        if (f.receiveHz)
            m_foundReceiveHz = f.receiveHz;
        m_readingFound = false;
        onPassState();
    });
    connect(m_link.get(), &RadioLink::commandFailed, this, &DopplerRadio::onCommandFailed);
    if (m_wanted)
        m_link->open();
    return true;
}

void DopplerRadio::onCommandFailed(const QString &command, const QString &why)
{
    if (m_readingFound) {
        // Whatever failed, the radio was not read: a pass need not wait for it.
        m_readingFound = false;
        QMetaObject::invokeMethod(this, &DopplerRadio::onPassState, Qt::QueuedConnection);
    }
    // A radio that refuses every frequency would refuse twenty a second:
    // the same refusal is said once a minute, with how many were not said.
    if (why == m_lastFailure && m_sinceFailure.isValid() && m_sinceFailure.elapsed() < kRepeatedFailureMs) {
        ++m_failuresNotSaid;
        return;
    }
    QString line = tr("radio: %1: %2").arg(command, why);
    if (m_failuresNotSaid > 0)
        line += tr(" (%n more like the last not said)", nullptr, m_failuresNotSaid);
    emit logLine(line);
    m_lastFailure = why;
    m_failuresNotSaid = 0;
    m_sinceFailure.start();
}

QString DopplerRadio::setVfoLayout(radio::VfoLayout layout)
{
    if (m_link) {
        if (QString why = m_link->setVfoLayout(layout); !why.isEmpty())
            return why;
    }
    m_layout = layout;
    return {};
}

void DopplerRadio::connectRadio()
{
    m_wanted = true;
    m_reopenAttempt = 0;
    // The controller's radio opens with the rotator's link (see the constructor).
    if (isControllers() && !m_session->isConnected())
        return;
    if (m_link && m_link->state() == RadioLink::State::Closed)
        m_link->open();
}

void DopplerRadio::disconnectRadio()
{
    m_wanted = false;
    m_reopen.stop();
    m_reopenAttempt = 0;
    if (isSteering())
        end(tr("the radio was disconnected"));
    if (m_link)
        m_link->close();
}

void DopplerRadio::onLinkState(RadioLink::State state, const QString &detail)
{
    emit linkStateChanged(state, detail);
    switch (state) {
    case RadioLink::State::Opening:
        break;
    case RadioLink::State::Open:
        m_reopenAttempt = 0;
        // The link's detail names it (radio/radiolink.h).
        emit logLine(tr("radio: connected to %1; latency %2 ms, tuning step %3 Hz")
                         .arg(detail)
                         .arg(m_link->latencyMs())
                         .arg(m_link->tuningStepHz(), 0, 'f', 0));
        readFound();
        onPassState(); // a pass already up is tuned from now on
        break;
    case RadioLink::State::Closed:
        m_readingFound = false;
        if (isSteering())
            end(tr("the radio's link closed"));
        if (m_wanted) {
            emit logLine(tr("radio: %1").arg(detail)); // the detail names the link (radio/radiolink.h)
            scheduleReopen();
        }
        break;
    }
}

void DopplerRadio::scheduleReopen()
{
    // The controller's link comes back with the rotator's (see the constructor).
    if (isControllers() && !m_session->isConnected())
        return;
    const int seconds = kReopenSeconds[std::min<size_t>(size_t(m_reopenAttempt), kReopenSeconds.size() - 1)];
    ++m_reopenAttempt;
    m_reopen.start(seconds * 1000);
    emit reopenScheduled(m_reopenAttempt, seconds);
}

bool DopplerRadio::isControllers() const
{
    return m_link && m_link->uri() == QLatin1String(kControllerUri);
}

bool DopplerRadio::passIsUp() const
{
    return m_runner->isRunning() && m_runner->tracker().state() == Tracker::State::Tracking
           && m_runner->target().kind == tracking::TrackTarget::Kind::Satellite;
}

void DopplerRadio::onPassState()
{
    const Tracker::State state = m_runner->tracker().state();
    // The radio as it stands before AOS: read once as the pass is waited
    // for. (This runs again when that read is answered: asked again then,
    // the radio would be read back to back until AOS.)
    if (state == Tracker::State::Waiting && m_lastPassState != Tracker::State::Waiting && !isSteering())
        readFound();
    m_lastPassState = state;
    const bool up = passIsUp() && !m_held;
    if (up && !isSteering())
        begin();
    else if (!up && isSteering())
        end(state == Tracker::State::Done ? QStringLiteral("LOS") : tr("the pass ended"));
}

void DopplerRadio::readFound()
{
    if (!m_link || !m_link->isOpen() || !m_link->canReadBack() || m_readingFound)
        return;
    m_readingFound = true;
    m_link->readFrequencies();
}

QString DopplerRadio::describePlan() const
{
    const radio::SatelliteFrequencies &f = m_plan->frequencies;
    QString text = tr("downlink %1").arg(radio::groupedMegahertz(f.downlinkHz + f.downlinkOffsetHz));
    if (!m_plan->receiveMode.isEmpty())
        text += QLatin1Char(' ') + m_plan->receiveMode;
    if (f.uplinkHz) {
        text += tr(", uplink %1").arg(radio::groupedMegahertz(*f.uplinkHz + f.uplinkOffsetHz));
        if (!m_plan->transmitMode.isEmpty())
            text += QLatin1Char(' ') + m_plan->transmitMode;
    }
    switch (f.correct) {
    case radio::DopplerOn::Both:
        break;
    case radio::DopplerOn::DownlinkOnly:
        text += tr(", Doppler on the downlink only");
        break;
    case radio::DopplerOn::UplinkOnly:
        text += tr(", Doppler on the uplink only");
        break;
    }
    if (!m_plan->name.isEmpty())
        text += tr(" (%1)").arg(m_plan->name);
    return text;
}

void DopplerRadio::holdControl(bool held)
{
    if (held == m_held)
        return;
    m_held = held;
    if (held) {
        if (isSteering())
            end(tr("control stopped by the operator, the radio left as it is"), false);
        else
            emit logLine(tr("radio: control stopped by the operator"));
    } else {
        emit logLine(tr("radio: control resumed by the operator"));
    }
    emit controlHeldChanged(held);
    onPassState(); // a pass still up is tuned again
}

void DopplerRadio::begin()
{
    if (m_held || !m_plan || !m_link || !m_link->isOpen() || !m_steering || m_readingFound)
        return; // begun when the radio has been read (or could not be)
    const tracking::TrackTarget &target = m_runner->target();
    if (m_plan->noradId != 0 && m_plan->noradId != target.elements.catalogueNumber) {
        emit logLine(tr("radio: not tuned: its frequencies are for NORAD %1, the pass is of %2 (NORAD %3)")
                         .arg(m_plan->noradId)
                         .arg(target.name())
                         .arg(target.elements.catalogueNumber));
        return;
    }
    // The radio's modes and split first: the pacer keeps their order ahead
    // of the frequencies that follow.
    if (!m_plan->receiveMode.isEmpty())
        m_link->setMode(m_plan->receiveMode, 0);
    const bool tunesUplink = m_plan->frequencies.uplinkHz.has_value();
    if (tunesUplink) {
        m_link->setSplit(true);
        m_splitTurnedOn = true;
        if (!m_plan->transmitMode.isEmpty())
            m_link->setTransmitMode(m_plan->transmitMode, 0);
    }
    // The same sky the tracker follows, a copy of its own: lookAt() carries
    // the propagation on from call to call.
    auto sky = std::make_shared<tracking::TargetSky>(target);
    const sky::Site place = m_runner->station();
    m_steering->begin(m_plan->frequencies, [sky, place](double julian) -> std::optional<double> {
        const std::optional<sky::LookAngles> look = sky->lookAt(place, julian);
        return look ? std::optional<double>(look->rangeRateKmS) : std::nullopt;
    });
    m_steering->start(m_clock);
    m_worstReceive = m_worstTransmit = kNaN;
    m_sinceMeasured.start();
    emit logLine(tr("radio: AOS: tuning %1 for %2 on %3").arg(target.name(), describePlan(), m_link->uri()));
    emit steeringChanged(true);
}

void DopplerRadio::end(const QString &why, bool putBack)
{
    if (!m_steering || !m_steering->isSteering())
        return;
    m_lastFigures = m_steering->figures();
    m_steering->stop();
    m_steering->end();
    m_link->dropWaiting(); // none of the pass's frequencies lands after it
    if (putBack && m_restoreAfterPass)
        this->putBack();
    m_splitTurnedOn = false;
    emit logLine(tr("radio: %1: Doppler %2").arg(why, radio::describeFigures(m_lastFigures)));
    emit steeringChanged(false);
}

void DopplerRadio::putBack()
{
    if (!m_link || !m_link->isOpen())
        return;
    if (m_splitTurnedOn) {
        m_link->setSplit(false);
        m_splitTurnedOn = false;
    }
    if (m_foundReceiveHz) {
        m_link->setReceiveHz(*m_foundReceiveHz);
        noteFrequencies(m_foundReceiveHz, std::nullopt);
    }
}

void DopplerRadio::noteFrequencies(std::optional<double> receiveHz, std::optional<double> transmitHz)
{
    const radio::RadioFrequencies before = m_frequencies;
    if (receiveHz && std::isfinite(*receiveHz))
        m_frequencies.receiveHz = receiveHz;
    if (transmitHz && std::isfinite(*transmitHz))
        m_frequencies.transmitHz = transmitHz;
    if (m_frequencies.receiveHz != before.receiveHz || m_frequencies.transmitHz != before.transmitHz)
        emit frequenciesChanged();
}

void DopplerRadio::setPlan(const std::optional<RadioPlan> &plan)
{
    m_plan = plan;
    if (isSteering())
        end(tr("new frequencies"), false);
    onPassState();
}

QString DopplerRadio::tuneBy(double hz)
{
    if (m_held)
        return tr("radio control is stopped");
    if (!isSteering())
        return tr("the radio is tuned only during a pass");
    QString why;
    if (m_steering->retuneBy(hz, &why) == 0.0)
        return why;
    return {};
}

radio::DopplerFigures DopplerRadio::figures() const
{
    return isSteering() ? m_steering->figures() : m_lastFigures;
}

void DopplerRadio::onMeasured(double receiveErrorHz, double transmitErrorHz)
{
    m_worstReceive = larger(m_worstReceive, receiveErrorHz);
    m_worstTransmit = larger(m_worstTransmit, transmitErrorHz);
    if (m_sinceMeasured.isValid() && m_sinceMeasured.elapsed() < kMeasuredIntervalMs)
        return;
    m_sinceMeasured.start();
    emit measured(m_worstReceive, m_worstTransmit);
    m_worstReceive = m_worstTransmit = kNaN;
}

} // namespace slew::station
