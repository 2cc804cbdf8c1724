// SPDX-License-Identifier: GPL-3.0-or-later
#include "hamlibradio.h"

#include "hamliblibrary.h"
#include "frequencytext.h"
#include "input/finitenumber.h"
#include "input/logtext.h"

#include <hamlib/rig.h>

#include <cmath>

namespace slew::radio {

namespace {

constexpr input::NumberRange kFrequencyRange{HamlibRadioLink::kMinHz, HamlibRadioLink::kMaxHz, " Hz"};
// A tuning step Slew takes from a radio: 1 Hz to 1 MHz.
constexpr input::NumberRange kStepRange{1, 1e6, " Hz"};
// Hamlib's passband: -1 keeps the radio's, 0 asks for the mode's default.
constexpr int kMinPassbandHz = -1;
constexpr int kMaxPassbandHz = 1000000;
constexpr qsizetype kMaxModeChars = 16;

// Whole hertz, what every radio takes.
double wholeHz(double hz)
{
    return double(std::llround(hz));
}

QString hzText(double hz)
{
    return QString::number(qint64(std::llround(hz)));
}

// A mode name of letters and digits only: what Hamlib's names are, and no
// byte that could end the C string early ("USB\0x" would read as USB).
bool isModeName(const QString &mode)
{
    if (mode.isEmpty() || mode.size() > kMaxModeChars)
        return false;
    for (const QChar c : mode) {
        if (!(c.isDigit() || (c >= u'A' && c <= u'Z') || (c >= u'a' && c <= u'z')))
            return false;
    }
    return true;
}

} // namespace

HamlibRadioLink::HamlibRadioLink(HamlibRadioConfig config, QObject *parent)
    : RadioLink(parent), m_config(std::move(config)), m_session(std::make_shared<std::atomic<int>>(0))
{
    prepareHamlib();
    connect(&m_pacer, &CommandPacer::ready, this, &HamlibRadioLink::send);
}

HamlibRadioLink::~HamlibRadioLink()
{
    if (!m_worker)
        return;
    // No result reaches this any more, no job of it is run, and the worker
    // frees the radio and ends once Hamlib returns from what it is doing.
    m_worker->disconnect(this);
    ++*m_session;
    m_worker->finishLater();
}

int HamlibRadioLink::liveWorkers()
{
    return HamlibWorker::liveCount();
}

void HamlibRadioLink::open()
{
    ++*m_session;
    m_pacer.clear();
    // Each opening starts knowing nothing of the radio.
    m_layout = m_wantedLayout;
    m_receiveRead.reset();
    m_splitOn = false;
    m_timeoutsInARow = 0;
    m_latencyMs = 0;
    m_tuningStepHz = 1.0;
    if (!m_worker) {
        m_worker = HamlibWorker::start(m_config, m_session);
        connect(m_worker, &HamlibWorker::done, this, &HamlibRadioLink::onDone, Qt::QueuedConnection);
    }
    setState(State::Opening, m_config.device.isEmpty()
                                 ? tr("%1: opening the %2").arg(label(), m_config.modelName)
                                 : tr("%1: opening the %2 on %3").arg(label(), m_config.modelName, m_config.device));
    m_pacer.submit({CommandKind::Read, QStringLiteral("rig_open"), int(Exchange::OpeningPort)});
}

QString HamlibRadioLink::setVfoLayout(VfoLayout layout)
{
    m_wantedLayout = layout;
    return {};
}

void HamlibRadioLink::close()
{
    if (m_state == State::Closed)
        return;
    m_state = State::Closed;
    leaveSession();
    emit stateChanged(State::Closed, tr("%1: closed").arg(label()));
}

void HamlibRadioLink::leaveSession()
{
    ++*m_session;
    m_pacer.clear();
    if (m_worker)
        m_worker->post(HamlibJob{*m_session, HamlibCall::Close});
}

void HamlibRadioLink::setState(State state, const QString &detail)
{
    m_state = state;
    emit stateChanged(state, detail);
}

void HamlibRadioLink::fail(const QString &reason)
{
    if (m_state == State::Closed)
        return;
    const std::optional<PacedCommand> pending = m_pacer.inFlight();
    m_state = State::Closed;
    leaveSession();
    // rig_open is the link's opening, not a command the traffic view saw.
    if (pending && Exchange(pending->tag) != Exchange::OpeningPort)
        emit commandFailed(pending->text, reason);
    emit stateChanged(State::Closed, reason);
}

// --- What the owner asks ---------------------------------------------------

bool HamlibRadioLink::acceptFrequency(const QString &command, double hz)
{
    QString why;
    if (input::checkNumber(hz, kFrequencyRange, &why))
        return true;
    emit commandFailed(QStringLiteral("%1 %2").arg(command).arg(hz), tr("not sent: %1").arg(why));
    return false;
}

void HamlibRadioLink::submit(CommandKind kind, Exchange exchange, const QString &text, double hz, quint64 mode,
                             qint64 passbandHz)
{
    if (m_state != State::Open) {
        emit commandFailed(text, tr("not sent: %1 is not open").arg(m_config.uri));
        return;
    }
    m_newest[kind] = Values{hz, mode, passbandHz};
    m_pacer.submit({kind, text, int(exchange)});
}

QString HamlibRadioLink::text(const char *call, Path path, const QString &arguments) const
{
    QString line = QLatin1String(call);
    if (m_layout == VfoLayout::MainSub)
        line += path == Path::Receive ? QStringLiteral(" Sub") : QStringLiteral(" Main");
    if (!arguments.isEmpty())
        line += QLatin1Char(' ') + arguments;
    return line;
}

void HamlibRadioLink::setReceiveHz(double hz)
{
    if (acceptFrequency(QStringLiteral("set_freq"), hz))
        submit(CommandKind::ReceiveFrequency, Exchange::SetReceive, text("set_freq", Path::Receive, hzText(hz)),
               wholeHz(hz));
}

void HamlibRadioLink::setTransmitHz(double hz)
{
    // With Main/Sub the transmit VFO's own frequency; with split, the split frequency.
    const char *call = m_layout == VfoLayout::MainSub ? "set_freq" : "set_split_freq";
    if (acceptFrequency(QLatin1String(call), hz))
        submit(CommandKind::TransmitFrequency, Exchange::SetTransmit, text(call, Path::Transmit, hzText(hz)),
               wholeHz(hz));
}

void HamlibRadioLink::setSplit(bool on)
{
    if (m_layout == VfoLayout::MainSub)
        return; // Main and Sub are the two paths already: no split
    if (on)
        submit(CommandKind::Split, Exchange::SetSplitOn, QStringLiteral("set_split_vfo 1 VFOB"));
    else
        submit(CommandKind::Split, Exchange::SetSplitOff, QStringLiteral("set_split_vfo 0 VFOA"));
}

void HamlibRadioLink::setMode(const QString &mode, int passbandHz)
{
    submitMode(CommandKind::Mode, Exchange::SetMode, Path::Receive, mode, passbandHz);
}

void HamlibRadioLink::setTransmitMode(const QString &mode, int passbandHz)
{
    submitMode(CommandKind::TransmitMode, Exchange::SetTransmitMode, Path::Transmit, mode, passbandHz);
}

void HamlibRadioLink::submitMode(CommandKind kind, Exchange exchange, Path path, const QString &mode, int passbandHz)
{
    // With Main/Sub each path's VFO has its own mode; with split, the transmit side's is the split mode.
    const char *call = path == Path::Transmit && m_layout == VfoLayout::Split ? "set_split_mode" : "set_mode";
    const QString command = text(call, path, QStringLiteral("%1 %2").arg(mode).arg(passbandHz));
    if (!isModeName(mode)) {
        emit commandFailed(input::loggableText(command, 60),
                           tr("not sent: a mode is a Hamlib mode name of letters and digits (USB, FM, PKTUSB)"));
        return;
    }
    const rmode_t parsed = rig_parse_mode(mode.toLatin1().constData());
    if (parsed == RIG_MODE_NONE) {
        emit commandFailed(command, tr("not sent: Hamlib knows no mode '%1' (its names: USB, LSB, CW, FM, AM, "
                                       "PKTUSB, ...; capitals)")
                                        .arg(mode));
        return;
    }
    if (passbandHz < kMinPassbandHz || passbandHz > kMaxPassbandHz) {
        emit commandFailed(command, tr("not sent: a passband is from %1 to %2 Hz (0: the mode's default)")
                                        .arg(kMinPassbandHz)
                                        .arg(kMaxPassbandHz));
        return;
    }
    submit(kind, exchange, command, 0, quint64(parsed), passbandHz);
}

void HamlibRadioLink::readFrequencies()
{
    submit(CommandKind::Read, Exchange::ReadReceive, text("get_freq", Path::Receive));
}

// --- The worker ------------------------------------------------------------

HamlibJob HamlibRadioLink::jobFor(const PacedCommand &command) const
{
    const bool mainSub = m_layout == VfoLayout::MainSub;
    const HamlibVfo receive = mainSub ? HamlibVfo::Sub : HamlibVfo::Current;
    const auto newest = m_newest.find(command.kind);
    const Values values = newest != m_newest.end() ? newest->second : Values{};
    HamlibJob job;
    job.session = *m_session;
    job.vfo = receive;
    switch (Exchange(command.tag)) {
    case Exchange::OpeningPort:
        job.call = HamlibCall::Open;
        break;
    case Exchange::OpeningRead:
    case Exchange::ReadReceive:
        job.call = HamlibCall::GetFreq;
        break;
    case Exchange::OpeningLatency:
        job.call = HamlibCall::SetFreq;
        job.hz = m_receiveRead.value_or(0);
        break;
    case Exchange::OpeningStep:
        job.call = HamlibCall::GetStep;
        break;
    case Exchange::OpeningSplit:
        job.call = HamlibCall::GetSplit;
        break;
    case Exchange::SetReceive:
        job.call = HamlibCall::SetFreq;
        job.hz = values.hz;
        break;
    case Exchange::SetTransmit:
        job.call = mainSub ? HamlibCall::SetFreq : HamlibCall::SetSplitFreq;
        job.vfo = mainSub ? HamlibVfo::Main : HamlibVfo::Current;
        job.hz = values.hz;
        break;
    case Exchange::SetSplitOn:
        job.call = HamlibCall::SplitOn;
        break;
    case Exchange::SetSplitOff:
        job.call = HamlibCall::SplitOff;
        break;
    case Exchange::SetMode:
        job.call = HamlibCall::SetMode;
        job.mode = values.mode;
        job.passbandHz = values.passbandHz;
        break;
    case Exchange::SetTransmitMode:
        job.call = mainSub ? HamlibCall::SetMode : HamlibCall::SetSplitMode;
        job.vfo = mainSub ? HamlibVfo::Main : HamlibVfo::Current;
        job.mode = values.mode;
        job.passbandHz = values.passbandHz;
        break;
    case Exchange::ReadTransmit:
        job.call = mainSub ? HamlibCall::GetFreq : HamlibCall::GetSplitFreq;
        job.vfo = mainSub ? HamlibVfo::Main : HamlibVfo::Current;
        break;
    }
    return job;
}

void HamlibRadioLink::send(const PacedCommand &command)
{
    m_sentAt.start();
    HamlibJob job = jobFor(command);
    job.serial = ++m_lastSerial;
    m_worker->post(job);
    if (Exchange(command.tag) != Exchange::OpeningPort)
        emit commandSent(command.text);
}

void HamlibRadioLink::onDone(const HamlibResult &result)
{
    // A result of a session this link has left, or of nothing it waits for:
    // only the answer to the job on the wire now is that command's (a read
    // of the transmit frequency taken for the receive one's answer would
    // be followed as a turn of the operator's dial).
    if (result.session != *m_session || !m_pacer.inFlight() || result.serial != m_lastSerial)
        return;
    const PacedCommand command = *m_pacer.inFlight();
    finishExchange(command, result);
}

bool HamlibRadioLink::isLoss(int code)
{
    if (code == -RIG_ETIMEOUT)
        return ++m_timeoutsInARow >= kTimeoutsBeforeClosing;
    m_timeoutsInARow = 0;
    return code == -RIG_EIO || code == -RIG_EPROTO;
}

void HamlibRadioLink::finishExchange(const PacedCommand &command, const HamlibResult &result)
{
    const Exchange exchange = Exchange(command.tag);
    const bool failed = result.code != RIG_OK;
    const QString words = failed ? hamlibErrorWords(result.code) : QString();

    if (exchange == Exchange::OpeningPort) {
        if (failed) {
            const QString where = m_config.device.isEmpty() ? tr("the %1").arg(m_config.modelName) : m_config.device;
            QString reason = tr("%1: cannot open %2: %3").arg(label(), where, words);
            if (!result.detail.isEmpty())
                reason += tr(" (%1)").arg(result.detail);
            fail(reason);
            return;
        }
        m_pacer.finished(PacedCommand{CommandKind::Read, text("get_freq", Path::Receive), int(Exchange::OpeningRead)});
        return;
    }
    if (isLoss(result.code)) {
        QString reason = tr("%1: %2 failed: %3").arg(label(), command.text, words);
        if (result.code == -RIG_ETIMEOUT)
            reason += tr(", %1 times in a row").arg(m_timeoutsInARow);
        fail(reason);
        return;
    }

    QString failure = failed ? tr("failed: %1").arg(words) : QString(); // why this command did nothing
    std::optional<PacedCommand> next;
    std::optional<RadioFrequencies> read;
    bool opened = false;

    // A frequency read back: finite and in range; else `failure` says why.
    auto frequency = [&]() -> std::optional<double> {
        if (failed)
            return std::nullopt;
        QString why;
        if (!input::checkNumber(result.value, kFrequencyRange, &why)) {
            failure = tr("unusable answer: %1").arg(why);
            return std::nullopt;
        }
        return result.value;
    };

    switch (exchange) {
    case Exchange::OpeningPort:
        break; // above
    case Exchange::OpeningRead: {
        const std::optional<double> hz = frequency();
        if (!hz) {
            fail(tr("%1: cannot read the frequency: %2").arg(label(), failure));
            return;
        }
        m_receiveRead = wholeHz(*hz);
        next = PacedCommand{CommandKind::ReceiveFrequency, text("set_freq", Path::Receive, hzText(*hz)),
                            int(Exchange::OpeningLatency)};
        break;
    }
    case Exchange::OpeningLatency:
        if (!failed)
            m_latencyMs = int(m_sentAt.elapsed());
        next = PacedCommand{CommandKind::Read, text("get_ts", Path::Receive), int(Exchange::OpeningStep)};
        break;
    case Exchange::OpeningStep:
        // The worker gives 1 Hz where the radio and the model say nothing.
        m_tuningStepHz = kStepRange.contains(result.value) ? result.value : 1.0;
        // Whether split is on already (the operator's, or a pass before):
        // reads then ask the transmit frequency too.
        if (m_layout == VfoLayout::Split)
            next = PacedCommand{CommandKind::Read, QStringLiteral("get_split_vfo"), int(Exchange::OpeningSplit)};
        else
            opened = true;
        break;
    case Exchange::OpeningSplit:
        failure.clear(); // a backend without get_split_vfo: split is then taken as off
        m_splitOn = !failed && result.value == 1;
        opened = true;
        break;
    case Exchange::SetSplitOn:
        if (!failed)
            m_splitOn = true;
        break;
    case Exchange::SetSplitOff:
        if (!failed)
            m_splitOn = false;
        break;
    case Exchange::SetReceive:
    case Exchange::SetTransmit:
    case Exchange::SetMode:
    case Exchange::SetTransmitMode:
        break;
    case Exchange::ReadReceive: {
        const std::optional<double> hz = frequency();
        if (!hz)
            break;
        if (m_layout == VfoLayout::MainSub) {
            m_receiveRead = hz;
            next = PacedCommand{CommandKind::Read, text("get_freq", Path::Transmit), int(Exchange::ReadTransmit)};
        } else if (m_splitOn) {
            m_receiveRead = hz;
            next = PacedCommand{CommandKind::Read, QStringLiteral("get_split_freq"), int(Exchange::ReadTransmit)};
        } else {
            read = RadioFrequencies{hz, std::nullopt};
        }
        break;
    }
    case Exchange::ReadTransmit: {
        const std::optional<double> hz = frequency();
        if (hz)
            read = RadioFrequencies{m_receiveRead, hz};
        break;
    }
    }

    m_pacer.finished(next);
    if (!failure.isEmpty())
        emit commandFailed(command.text, failure);
    if (read)
        emit frequenciesRead(*read);
    if (opened)
        becomeOpen();
}

QString HamlibRadioLink::label() const
{
    // "sim: closed", not "sim:: closed": a URI may end in its colon.
    return m_config.uri.endsWith(QLatin1Char(':')) ? m_config.uri.chopped(1) : m_config.uri;
}

void HamlibRadioLink::becomeOpen()
{
    if (m_state != State::Opening)
        return; // closed by a handler of the signals before
    // The frequency as the operator reads it off the dial; none when the
    // first reading had none.
    const QString where = m_receiveRead ? tr(" at %1").arg(groupedMegahertz(*m_receiveRead)) : QString();
    setState(State::Open, tr("%1: open%2; a set answered in %3 ms").arg(label(), where).arg(m_latencyMs));
}

} // namespace slew::radio
