// SPDX-License-Identifier: GPL-3.0-or-later
#include "dopplersteering.h"

#include "frequencytext.h"
#include "radiolink.h"

#include "sky/observation.h"
#include "tracking/stationclock.h"


#include <algorithm>
#include <cmath>
#include <limits>

namespace slew::radio {

namespace {

// How long a frequency Slew sent may still be read back: the radio's
// latency and a read on its way, with room to spare.
constexpr qint64 kOwnEchoMs = 3000;
constexpr size_t kRecentSent = 32;
// A read unanswered this long has failed (a failure brings no reading); a
// read answered later still is judged against kOwnEchoMs of Slew's own.
constexpr qint64 kReadGivenUpMs = 2000;
constexpr double kMsPerDay = 86400000.0;
// The Doppler rate is taken over this span around the moment.
constexpr double kRateSpanS = 0.5;
// A frequency is held at most this long before the next is due: the lead
// by half the hold never reaches further ahead than half of it.
constexpr double kLongestHoldS = 2.0;

// Readings this close to a frequency are that frequency: two steps, for a
// radio that rounds what it is sent to its own step, and never under 5 Hz,
// below any turn of a dial worth following.
double sameFrequencyHz(double stepHz)
{
    return std::max(2.0 * stepHz, 5.0);
}

} // namespace

QString describeFigures(const DopplerFigures &f)
{
    QString text = QObject::tr("error RMS %1, worst %2 over %3 readings; %4 frequencies sent")
                       .arg(tenthsOfHertz(f.rmsHz), tenthsOfHertz(f.worstHz))
                       .arg(f.samples)
                       .arg(f.commands);
    if (std::abs(f.dialOffsetHz) >= 0.5) // as signedHertz() would write it: not 0
        text += QObject::tr("; dial offset %1").arg(signedHertz(f.dialOffsetHz));
    return text;
}

DopplerSteering::DopplerSteering(RadioLink *link, QObject *parent) : QObject(parent), m_link(link)
{
    connect(link, &RadioLink::frequenciesRead, this, &DopplerSteering::onRead);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        if (m_clock)
            step(m_clock->nowJulian(), m_monotonic.elapsed());
    });
    m_monotonic.start();
    // A link that closes or opens again has lost whatever was on its way.
    connect(link, &RadioLink::stateChanged, this, [this] {
        m_readPending = false;
        m_recentReceive.clear();
    });
}

void DopplerSteering::begin(const SatelliteFrequencies &satellite, RangeRate rangeRate)
{
    m_satellite = satellite;
    m_dialOffsetHz = 0;
    m_rangeRate = std::move(rangeRate);
    m_sentReceive.reset();
    m_sentTransmit.reset();
    m_sendTimes.clear();
    m_dial.reset();
    m_receiveTaken = true;
    // What is on its way to the radio belongs to the link, not to the
    // pass: a read still unanswered stays awaited (asked again now, the
    // pacer would put the new read where the old one stood, ahead of
    // this pass's first frequency), and the frequencies sent before are
    // still Slew's own when a reading shows them (m_recentReceive). Both
    // matter when begin() comes again on an open link (the window's Apply
    // during a pass): forgotten, the last frequency of before read back
    // after the first of now is taken for a turn of the dial.
    m_receivesSent = 0;
    m_receivesBeforeRead = 0;
    m_heldReceive.clear();
    m_heldTransmit.clear();
    m_sumSquares = 0;
    m_worst = 0;
    m_samples = 0;
    m_commandsAtBegin = m_commandsSent;
}

DopplerFigures DopplerSteering::figures() const
{
    DopplerFigures f;
    f.samples = m_samples;
    f.rmsHz = m_samples > 0 ? std::sqrt(m_sumSquares / m_samples) : 0.0;
    f.worstHz = m_worst;
    f.commands = m_commandsSent - m_commandsAtBegin;
    f.dialOffsetHz = m_dialOffsetHz;
    return f;
}

SatelliteFrequencies DopplerSteering::retuned(double dialOffsetHz) const
{
    SatelliteFrequencies moved = m_satellite;
    moved.downlinkHz += dialOffsetHz;
    if (moved.uplinkHz && moved.uplinkFollows != UplinkFollowsDial::No)
        *moved.uplinkHz += moved.uplinkFollows == UplinkFollowsDial::OppositeWay ? -dialOffsetHz : dialOffsetHz;
    return moved;
}

void DopplerSteering::noteHeld(std::deque<Held> &held, double hz, qint64 fromMs) const
{
    held.push_back({hz, fromMs, m_dialOffsetHz});
    // Only the newest value already on the radio, and those still on
    // their way, are ever asked for.
    while (held.size() > kRecentSent)
        held.pop_front();
}

std::optional<DopplerSteering::Held> DopplerSteering::heldAt(const std::deque<Held> &held, qint64 nowMs)
{
    for (auto it = held.rbegin(); it != held.rend(); ++it) {
        if (it->fromMs <= nowMs)
            return *it;
    }
    return std::nullopt;
}

void DopplerSteering::measure()
{
    if (!m_rangeRate || m_dial)
        return;
    const std::optional<double> rangeRate = m_rangeRate(m_lastJulian);
    if (!rangeRate || !std::isfinite(*rangeRate))
        return;
    // Each frequency against the truth for the dial offset it was sent for.
    auto truthFor = [&](const Held &held) { return tuningFor(retuned(held.dialOffsetHz), *rangeRate); };
    double receiveError = std::numeric_limits<double>::quiet_NaN();
    double transmitError = std::numeric_limits<double>::quiet_NaN();
    auto count = [this](double error) {
        m_sumSquares += error * error;
        m_worst = std::max(m_worst, std::abs(error));
        ++m_samples;
    };
    if (const std::optional<Held> held = heldAt(m_heldReceive, m_nowMs)) {
        receiveError = held->hz - truthFor(*held).receiveHz;
        count(receiveError);
    }
    if (const std::optional<Held> held = heldAt(m_heldTransmit, m_nowMs)) {
        if (const std::optional<double> truth = truthFor(*held).transmitHz) {
            transmitError = held->hz - *truth;
            count(transmitError);
        }
    }
    if (std::isfinite(receiveError) || std::isfinite(transmitError))
        emit measured(receiveError, transmitError);
}

void DopplerSteering::end()
{
    m_rangeRate = nullptr;
    m_dial.reset();
}

void DopplerSteering::start(const tracking::StationClock *clock)
{
    m_clock = clock;
    m_timer.start(m_settings.stepMs);
}

void DopplerSteering::stop()
{
    m_timer.stop();
    m_clock = nullptr;
}

bool DopplerSteering::followsDial() const
{
    // A radio that answers no readings (a controller on Easycomm I) is
    // steered blind.
    return m_settings.followDial && m_link->canReadBack();
}

int DopplerSteering::leadMs() const
{
    return m_settings.leadMs >= 0 ? m_settings.leadMs : m_link->latencyMs();
}

double DopplerSteering::tuningStepHz() const
{
    return std::max(1.0, m_link->tuningStepHz());
}

void DopplerSteering::step(double julian, qint64 nowMs)
{
    m_lastJulian = julian;
    m_nowMs = nowMs;
    if (!m_rangeRate || !m_link->isOpen())
        return;
    // A read that fails is answered by no reading: given up after a while,
    // or the receive frequency would wait for it for the rest of the pass.
    if (m_readPending && nowMs - m_lastReadMs >= kReadGivenUpMs)
        m_readPending = false;
    // The dial is read again and again while it is followed; a new receive
    // frequency goes out when a reading has shown the last one taken.
    if (followsDial() && !m_readPending && (m_lastReadMs < 0 || nowMs - m_lastReadMs >= m_settings.readBackMs)) {
        m_readPending = true;
        m_receivesBeforeRead = m_receivesSent;
        m_lastReadMs = nowMs;
        m_link->readFrequencies(); // its answer may come at once (onRead)
    }
    sendDue();
    measure();
}

bool DopplerSteering::withinBudget()
{
    while (!m_sendTimes.empty() && m_nowMs - m_sendTimes.front() >= 1000)
        m_sendTimes.pop_front();
    return int(m_sendTimes.size()) < m_settings.maxCommandsPerSecond;
}

void DopplerSteering::noteSent()
{
    m_sendTimes.push_back(m_nowMs);
    ++m_commandsSent;
}

void DopplerSteering::sendDue()
{
    if (m_dial || !m_rangeRate || !m_link->isOpen())
        return; // the operator's hand is on the dial: nothing is sent over it
    // What will be due once the radio has taken the command, and how fast
    // it moves then.
    const double at = m_lastJulian + leadMs() / kMsPerDay;
    const std::optional<double> now = m_rangeRate(at);
    const std::optional<double> before = m_rangeRate(at - kRateSpanS / 2 / 86400.0);
    const std::optional<double> after = m_rangeRate(at + kRateSpanS / 2 / 86400.0);
    if (!now || !before || !after || !std::isfinite(*now) || !std::isfinite(*before) || !std::isfinite(*after))
        return;
    const SatelliteFrequencies satellite = this->satellite();
    const RadioTuning wanted = tuningFor(satellite, *now);
    const RadioTuning early = tuningFor(satellite, *before), late = tuningFor(satellite, *after);
    const double receiveRate = (late.receiveHz - early.receiveHz) / kRateSpanS; // Hz/s
    const double transmitRate = wanted.transmitHz ? (*late.transmitHz - *early.transmitHz) / kRateSpanS : 0.0;

    // The budget shared by rate^(2/3); each frequency's step from its share.
    const double receiveWeight = std::cbrt(receiveRate * receiveRate);
    const double transmitWeight = wanted.transmitHz ? std::cbrt(transmitRate * transmitRate) : 0.0;
    const double budget = std::max(1, m_settings.maxCommandsPerSecond);
    const double weights = receiveWeight + transmitWeight;
    auto stepFor = [&](double rate, double weight) {
        const double share = weights > 0 ? budget * weight / weights : budget;
        return std::max({m_settings.thresholdHz, tuningStepHz(), std::abs(rate) / std::max(share, 0.5)});
    };
    // Due once the frequency held lags the wanted one by half its step (it
    // was sent half a step ahead), or is off by a whole step either way.
    auto due = [](std::optional<double> held, double want, double rate, double step) {
        if (!held)
            return true;
        const double lag = (want - *held) * (rate >= 0 ? 1.0 : -1.0);
        return lag > step / 2 || std::abs(want - *held) > step;
    };
    // Half the hold ahead: the value that will be due in the middle of it.
    auto ahead = [](double want, double rate, double step) {
        if (rate == 0.0)
            return want;
        const double holdS = std::min(step / std::abs(rate), kLongestHoldS);
        return want + rate * holdS / 2;
    };
    bool sent = false;
    const double receiveStep = stepFor(receiveRate, receiveWeight);
    // While the dial is followed, a receive frequency goes out only in
    // answer to a reading that has just shown the last one taken: from a
    // timer instead, it could land on a turn made since that reading, and
    // the turn would never be seen.
    const bool receiveMayGo = !followsDial() || (m_receiveTaken && m_answeringRead);
    if (receiveMayGo && due(m_sentReceive, wanted.receiveHz, receiveRate, receiveStep) && withinBudget()) {
        const double hz = quantised(ahead(wanted.receiveHz, receiveRate, receiveStep), tuningStepHz());
        m_link->setReceiveHz(hz);
        m_sentReceive = hz;
        m_receiveTaken = false;
        m_recentReceive.push_back({hz, m_nowMs});
        if (m_recentReceive.size() > kRecentSent)
            m_recentReceive.pop_front();
        noteHeld(m_heldReceive, hz, m_nowMs + leadMs());
        ++m_receivesSent;
        noteSent();
        sent = true;
    }
    if (wanted.transmitHz) {
        const double transmitStep = stepFor(transmitRate, transmitWeight);
        if (due(m_sentTransmit, *wanted.transmitHz, transmitRate, transmitStep) && withinBudget()) {
            const double hz = quantised(ahead(*wanted.transmitHz, transmitRate, transmitStep), tuningStepHz());
            m_link->setTransmitHz(hz);
            m_sentTransmit = hz;
            noteHeld(m_heldTransmit, hz, m_nowMs + leadMs());
            noteSent();
            sent = true;
        }
    }
    if (sent && m_sentReceive)
        emit tuned(RadioTuning{*m_sentReceive, m_sentTransmit});
}

double DopplerSteering::retuneBy(double hz, QString *why)
{
    auto refuse = [why](const QString &reason) {
        if (why)
            *why = reason;
        return 0.0;
    };
    if (!m_rangeRate)
        return refuse(tr("no pass is being tuned"));
    if (m_dial)
        return refuse(tr("the radio's dial is being turned"));
    if (!std::isfinite(hz))
        return refuse(tr("not a step"));
    double wanted = m_dialOffsetHz + hz;
    if (const std::optional<Passband> &band = m_satellite.downlinkPassband) {
        // The plan's downlink (without calibration, as the passband is
        // listed) moved by the offset stays inside the passband.
        wanted = std::clamp(wanted, band->lowHz - m_satellite.downlinkHz, band->highHz - m_satellite.downlinkHz);
    }
    const double moved = wanted - m_dialOffsetHz;
    if (std::abs(moved) < 0.5)
        return refuse(hz > 0 ? tr("at the top of the passband") : tr("at the bottom of the passband"));
    m_dialOffsetHz = wanted;
    sendDue(); // the uplink now; the downlink in answer to the next reading (see sendDue)
    return moved;
}

bool DopplerSteering::isOwn(double receiveHz) const
{
    // A reading that matches a recent command is Slew's own, even an older
    // one that the radio had not yet replaced when it was read.
    const double tolerance = sameFrequencyHz(tuningStepHz());
    for (const Sent &s : m_recentReceive) {
        if (m_nowMs - s.atMs <= kOwnEchoMs && std::abs(s.hz - receiveHz) <= tolerance)
            return true;
    }
    return false;
}

void DopplerSteering::onRead(const RadioFrequencies &frequencies)
{
    m_answeringRead = true;
    judgeReading(frequencies);
    m_answeringRead = false;
}

void DopplerSteering::judgeReading(const RadioFrequencies &frequencies)
{
    m_readPending = false;
    if (!m_rangeRate || !followsDial())
        return;
    if (!m_sentReceive) {
        sendDue(); // the pass's first frequency, in answer to the first reading
        return;
    }
    if (!frequencies.receiveHz)
        return;
    // A read asked before Slew's first frequency of the pass shows where
    // the radio was left before it: no turn of the dial, and nothing to judge.
    if (m_receivesBeforeRead == 0)
        return;
    const double read = *frequencies.receiveHz;
    const double tolerance = sameFrequencyHz(tuningStepHz());
    if (!m_dial) {
        if (std::abs(read - *m_sentReceive) <= tolerance) {
            m_receiveTaken = true; // the radio holds what was sent last: the next may go
            sendDue();
            return;
        }
        if (isOwn(read))
            return; // an older command of Slew's: the last is not taken yet
        m_dial = Dial{read, m_nowMs}; // the operator's hand: hold still and watch
        return;
    }
    // A command of Slew's that was on its way when the hand moved lands
    // over the turn: the reading is Slew's, the operator's point is still
    // the one seen, and it is put back below.
    const bool overwritten = isOwn(read);
    if (!overwritten && std::abs(read - m_dial->hz) > tolerance) {
        m_dial = Dial{read, m_nowMs}; // still turning
        return;
    }
    if (m_nowMs - m_dial->sinceMs < m_settings.dialRestMs)
        return;
    adoptDial(overwritten);
}

void DopplerSteering::adoptDial(bool overwritten)
{
    const double point = m_dial->hz;
    // At rest: the operator's new point. It is heard on the ground; the
    // satellite's frequency behind it is what Doppler is corrected from, as
    // it was when the dial came to that point (the Doppler has moved on
    // while it rested, and that is no part of the operator's turn).
    const double pointJulian = m_lastJulian - double(m_nowMs - m_dial->sinceMs) / kMsPerDay;
    const std::optional<double> rangeRate = m_rangeRate(pointJulian);
    const bool corrected = m_satellite.correct != DopplerOn::UplinkOnly;
    const double atSatellite = corrected && rangeRate ? point / sky::dopplerFactor(*rangeRate) : point;
    const SatelliteFrequencies before = satellite();
    const double offset = atSatellite - (before.downlinkHz + before.downlinkOffsetHz);
    m_dialOffsetHz += offset; // the uplink follows through retuned()
    m_receiveTaken = true;
    m_dial.reset();
    if (overwritten) {
        m_sentReceive.reset(); // the radio holds Slew's old value: the operator's goes out now
    } else {
        // What the radio holds is right for now: no command sent back over it.
        m_sentReceive = point;
        m_recentReceive.push_back({point, m_nowMs});
        noteHeld(m_heldReceive, point, m_nowMs); // already on the radio
    }
    emit dialFollowed(offset);
    sendDue();
}

} // namespace slew::radio
