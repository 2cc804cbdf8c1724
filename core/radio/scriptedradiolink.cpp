// SPDX-License-Identifier: GPL-3.0-or-later
#include "scriptedradiolink.h"

#include "frequencytext.h"
#include "input/finitenumber.h"
#include "input/logtext.h"
#include "protocol/hamliberrors.h"
#include "radiolimits.h"

namespace slew::radio {

namespace {

using protocol::HamlibError;

// The number a read answered, in `range`; else nothing, and *failure says
// why (a refusal has said it already).
std::optional<double> valueIn(const RadioAnswer &answer, const input::NumberRange &range, QString *failure)
{
    if (answer.code != 0)
        return std::nullopt;
    if (!answer.value) {
        *failure = QObject::tr("the answer held no value");
        return std::nullopt;
    }
    QString why;
    const std::optional<double> v = input::numberIn(*answer.value, range, &why);
    if (!v)
        *failure = QObject::tr("unusable answer: %1").arg(why);
    return v;
}

RadioCommand frequencyCommand(RadioCommand::Call call, RadioPath path, double hz = 0)
{
    RadioCommand c;
    c.call = call;
    c.path = path;
    c.hz = hz;
    return c;
}

} // namespace

ScriptedRadioLink::ScriptedRadioLink(QString uri, std::unique_ptr<ExchangePerformer> performer, QObject *parent)
    : RadioLink(parent), m_uri(std::move(uri)), m_performer(std::move(performer)),
      m_replyTimeoutMs(limits::kReplyTimeoutMs), m_tuningStepHz(limits::kUnknownStepHz)
{
    connect(&m_pacer, &CommandPacer::ready, this, &ScriptedRadioLink::onReady);
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, &ScriptedRadioLink::onDeadline);
    connect(m_performer.get(), &ExchangePerformer::opened, this, &ScriptedRadioLink::onOpened);
    connect(m_performer.get(), &ExchangePerformer::answered, this, &ScriptedRadioLink::onAnswered);
    connect(m_performer.get(), &ExchangePerformer::lost, this,
            [this](const QString &reason) { fail(tr("%1: %2").arg(label(), reason)); });
    connect(m_performer.get(), &ExchangePerformer::said, this, &RadioLink::commandSent);
}

ScriptedRadioLink::~ScriptedRadioLink()
{
    // The performer goes after the pacer and the timer: nothing it says
    // while it ends may reach them.
    m_performer->disconnect(this);
}

QString ScriptedRadioLink::label() const
{
    return m_uri.endsWith(QLatin1Char(':')) ? m_uri.chopped(1) : m_uri;
}

void ScriptedRadioLink::setState(State state, const QString &detail)
{
    m_state = state;
    emit stateChanged(state, detail);
}

void ScriptedRadioLink::open()
{
    m_pacer.clear();
    m_deadline.stop();
    // Each opening starts knowing nothing of the radio.
    ++m_openings;
    m_layout = m_wantedLayout;
    m_receiveRead.reset();
    m_transmitRead.reset();
    m_splitOn = false;
    m_timeoutsInARow = 0;
    m_latencyMs = 0;
    m_tuningStepHz = limits::kUnknownStepHz;
    setState(State::Opening, tr("%1: %2").arg(label(), m_performer->reaching()));
    m_performer->open(m_layout);
}

void ScriptedRadioLink::close()
{
    if (m_state == State::Closed)
        return;
    m_state = State::Closed;
    m_pacer.clear();
    m_deadline.stop();
    m_performer->close();
    emit stateChanged(State::Closed, tr("%1: closed").arg(label()));
}

void ScriptedRadioLink::fail(const QString &reason)
{
    if (m_state == State::Closed)
        return;
    const bool pending = m_pacer.inFlight().has_value();
    const QString pendingText = pending ? m_performer->text(m_onTheWire) : QString();
    m_state = State::Closed;
    m_pacer.clear();
    m_deadline.stop();
    m_performer->abort();
    if (pending)
        emit commandFailed(pendingText, reason);
    emit stateChanged(State::Closed, reason);
}

QString ScriptedRadioLink::setVfoLayout(VfoLayout layout)
{
    m_wantedLayout = layout;
    return {};
}

// --- What the owner asks ---------------------------------------------------

// The shared limits' words (radiolimits.h), as the controller's link says them too.
bool ScriptedRadioLink::acceptFrequency(const RadioCommand &command)
{
    const QString why = limits::frequencyRefusal(command.hz);
    if (why.isEmpty())
        return true;
    emit commandFailed(m_performer->text(command), why);
    return false;
}

bool ScriptedRadioLink::acceptMode(const RadioCommand &command)
{
    const QString why = limits::modeRefusal(command.mode, command.passbandHz);
    if (why.isEmpty())
        return true;
    // A mode name that is refused may hold a line end or a NUL.
    emit commandFailed(input::loggableText(m_performer->text(command), 60), why);
    return false;
}

void ScriptedRadioLink::submit(CommandKind kind, const RadioCommand &command, Place place)
{
    const QString text = m_performer->text(command);
    if (m_state != State::Open) {
        emit commandFailed(text, tr("not sent: %1 is not open").arg(m_uri));
        return;
    }
    if (const QString why = m_performer->refusal(command); !why.isEmpty()) {
        emit commandFailed(text, tr("not sent: %1").arg(why));
        return;
    }
    m_newest[kind] = command;
    if (place == Place::First)
        m_pacer.submitFirst(paced(Step::Set, kind, command));
    else
        m_pacer.submit(paced(Step::Set, kind, command));
}

void ScriptedRadioLink::setReceiveHz(double hz)
{
    const RadioCommand command = frequencyCommand(RadioCommand::Call::SetFrequency, RadioPath::Receive, hz);
    if (acceptFrequency(command))
        submit(CommandKind::ReceiveFrequency, command, Place::First); // why first: the header
}

void ScriptedRadioLink::setTransmitHz(double hz)
{
    const RadioCommand command = frequencyCommand(RadioCommand::Call::SetFrequency, RadioPath::Transmit, hz);
    if (acceptFrequency(command))
        submit(CommandKind::TransmitFrequency, command);
}

void ScriptedRadioLink::setSplit(bool on)
{
    if (m_layout == VfoLayout::MainSub)
        return; // Main and Sub are the two paths already: no split
    RadioCommand command;
    command.call = RadioCommand::Call::SetSplit;
    command.on = on;
    submit(CommandKind::Split, command);
}

void ScriptedRadioLink::setMode(const QString &mode, int passbandHz)
{
    RadioCommand command;
    command.call = RadioCommand::Call::SetMode;
    command.mode = mode;
    command.passbandHz = passbandHz;
    if (acceptMode(command))
        submit(CommandKind::Mode, command);
}

void ScriptedRadioLink::setTransmitMode(const QString &mode, int passbandHz)
{
    // With Main/Sub the transmit VFO's own mode; with split, the split mode.
    RadioCommand command;
    command.call = RadioCommand::Call::SetMode;
    command.path = RadioPath::Transmit;
    command.mode = mode;
    command.passbandHz = passbandHz;
    if (acceptMode(command))
        submit(CommandKind::TransmitMode, command);
}

void ScriptedRadioLink::readFrequencies()
{
    const RadioCommand receive = frequencyCommand(RadioCommand::Call::ReadFrequency, RadioPath::Receive);
    if (m_state != State::Open) {
        emit commandFailed(m_performer->text(receive), tr("not sent: %1 is not open").arg(m_uri));
        return;
    }
    m_pacer.submit(paced(Step::Read, CommandKind::Read, receive));
}

// --- The exchanges ---------------------------------------------------------

PacedCommand ScriptedRadioLink::paced(Step step, CommandKind kind, const RadioCommand &command) const
{
    return PacedCommand{kind, m_performer->text(command), int(step)};
}

RadioCommand ScriptedRadioLink::commandFor(const PacedCommand &paced) const
{
    using Call = RadioCommand::Call;
    switch (Step(paced.tag)) {
    case Step::Read:
        // The transmit frequency first, where it is read: the receive
        // frequency is read last (the header says why). Split may have
        // come on since the read was asked.
        return frequencyCommand(Call::ReadFrequency, readsTransmit() ? RadioPath::Transmit : RadioPath::Receive);
    case Step::OpeningRead:
    case Step::ReadReceive:
        return frequencyCommand(Call::ReadFrequency, RadioPath::Receive);
    case Step::OpeningLatency:
        return frequencyCommand(Call::SetFrequency, RadioPath::Receive, m_receiveRead.value_or(0));
    case Step::OpeningStep:
        return frequencyCommand(Call::ReadStep, RadioPath::Receive);
    case Step::OpeningSplit:
        return frequencyCommand(Call::ReadSplit, RadioPath::Receive);
    case Step::Set:
        break;
    }
    return m_newest.at(paced.kind);
}

bool ScriptedRadioLink::readsTransmit() const
{
    return m_layout == VfoLayout::MainSub || m_splitOn;
}

void ScriptedRadioLink::onOpened()
{
    if (m_state != State::Opening)
        return;
    const RadioCommand read = frequencyCommand(RadioCommand::Call::ReadFrequency, RadioPath::Receive);
    m_pacer.submit(paced(Step::OpeningRead, CommandKind::Read, read));
}

void ScriptedRadioLink::onReady(const PacedCommand &paced)
{
    m_onTheWire = commandFor(paced);
    m_sentAt.start();
    m_deadline.start(m_replyTimeoutMs);
    emit commandSent(m_performer->text(m_onTheWire));
    // A handler of commandSent may have closed the link.
    if (m_state != State::Closed && m_pacer.inFlight())
        m_performer->perform(m_onTheWire);
}

void ScriptedRadioLink::onAnswered(const RadioAnswer &answer)
{
    if (m_state == State::Closed || !m_pacer.inFlight())
        return; // an answer that no longer has a command
    m_deadline.stop();
    const PacedCommand command = *m_pacer.inFlight();
    finishExchange(command, answer);
}

void ScriptedRadioLink::onDeadline()
{
    const QString command = m_pacer.inFlight() ? m_performer->text(m_onTheWire) : QString();
    fail(tr("%1: %2 did not answer '%3' within %4 s")
             .arg(label(), m_performer->peerName(), command)
             .arg(m_replyTimeoutMs / 1000.0));
}

bool ScriptedRadioLink::givesUp(int code)
{
    if (code == -int(HamlibError::Timeout))
        return ++m_timeoutsInARow >= limits::kTimeoutsBeforeClosing;
    m_timeoutsInARow = 0;
    return code == -int(HamlibError::Io) || code == -int(HamlibError::Protocol);
}

void ScriptedRadioLink::finishExchange(const PacedCommand &command, const RadioAnswer &answer)
{
    const Step step = Step(command.tag);
    const RadioCommand performed = m_onTheWire; // the pacer may put the next one on the wire below
    Outcome outcome;
    outcome.failure = answer.code != 0 ? answer.why : QString();
    const bool gone = givesUp(answer.code);
    if (step == Step::OpeningRead) {
        // Without the radio's frequency there is nothing to time or to steer from.
        const std::optional<double> hz = valueIn(answer, limits::kFrequencyRange, &outcome.failure);
        if (!hz) {
            fail(tr("%1: cannot read the frequency: %2").arg(label(), outcome.failure));
            return;
        }
        m_receiveRead = hz;
        outcome.next = paced(Step::OpeningLatency, CommandKind::ReceiveFrequency,
                             frequencyCommand(RadioCommand::Call::SetFrequency, RadioPath::Receive, *hz));
    } else if (gone) {
        QString reason = tr("%1: %2 %3").arg(label(), m_performer->text(performed), answer.why);
        if (answer.code == -int(HamlibError::Timeout))
            reason += tr(", %1 times in a row").arg(m_timeoutsInARow);
        fail(reason);
        return;
    } else if (step == Step::OpeningLatency || step == Step::OpeningStep || step == Step::OpeningSplit) {
        takeOpeningAnswer(step, answer, outcome);
    } else {
        takeAnswer(step, performed, answer, outcome);
    }

    // Told while this command still holds the wire: what is sent in answer
    // goes next (the header says why). A handler may close the link, and
    // open it again.
    const int opening = m_openings;
    if (!outcome.failure.isEmpty())
        emit commandFailed(m_performer->text(performed), outcome.failure);
    if (outcome.read)
        emit frequenciesRead(*outcome.read);
    if (m_state == State::Closed || opening != m_openings)
        return;
    m_pacer.finished(outcome.next);
    if (outcome.opened)
        becomeOpen();
}

void ScriptedRadioLink::takeOpeningAnswer(Step step, const RadioAnswer &answer, Outcome &outcome)
{
    const bool refused = answer.code != 0;
    switch (step) {
    case Step::OpeningLatency:
        if (!refused)
            m_latencyMs = int(m_sentAt.elapsed()); // why the set: radiolimits.h
        outcome.next = paced(Step::OpeningStep, CommandKind::Read,
                             frequencyCommand(RadioCommand::Call::ReadStep, RadioPath::Receive));
        return;
    case Step::OpeningStep:
        if (refused)
            outcome.failure.clear(); // a backend without get_ts: the step is not known, no fault of the link
        else if (const std::optional<double> hz = valueIn(answer, limits::kStepRange, &outcome.failure); hz && *hz > 0)
            m_tuningStepHz = *hz;
        // Whether split is on already (the operator's, or a pass before):
        // reads then ask the transmit frequency too.
        if (m_layout == VfoLayout::Split && m_performer->canReadSplit())
            outcome.next = paced(Step::OpeningSplit, CommandKind::Read,
                                 frequencyCommand(RadioCommand::Call::ReadSplit, RadioPath::Receive));
        else
            outcome.opened = true;
        return;
    case Step::OpeningSplit:
        outcome.failure.clear(); // a backend without get_split_vfo: split is then taken as off
        m_splitOn = !refused && answer.value && answer.value->trimmed() == QLatin1String("1");
        outcome.opened = true;
        return;
    default:
        return;
    }
}

void ScriptedRadioLink::takeAnswer(Step step, const RadioCommand &performed, const RadioAnswer &answer,
                                   Outcome &outcome)
{
    if (step == Step::Set) {
        if (answer.code == 0 && performed.call == RadioCommand::Call::SetSplit)
            m_splitOn = performed.on;
        return;
    }
    const std::optional<double> hz = valueIn(answer, limits::kFrequencyRange, &outcome.failure);
    if (!hz)
        return; // a half read is no reading
    if (performed.path == RadioPath::Transmit) {
        m_transmitRead = hz;
        outcome.next = paced(Step::ReadReceive, CommandKind::Read,
                             frequencyCommand(RadioCommand::Call::ReadFrequency, RadioPath::Receive));
        return;
    }
    // A read that started with the receive frequency has no transmit half.
    const std::optional<double> transmit = step == Step::ReadReceive ? m_transmitRead : std::nullopt;
    outcome.read = RadioFrequencies{hz, transmit};
}

void ScriptedRadioLink::becomeOpen()
{
    if (m_state != State::Opening)
        return; // closed by a handler of the signals before
    // The frequency as the operator reads it off the dial.
    const QString where = m_receiveRead ? tr(" at %1").arg(groupedMegahertz(*m_receiveRead)) : QString();
    setState(State::Open, tr("%1: open%2; a set answered in %3 ms").arg(label(), where).arg(m_latencyMs));
}

} // namespace slew::radio
