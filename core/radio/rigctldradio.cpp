// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigctldradio.h"

#include "frequencytext.h"
#include "input/finitenumber.h"
#include "input/logtext.h"
#include "protocol/hamliberrors.h"

#include <cmath>

namespace slew::radio {

namespace {

constexpr input::NumberRange kFrequencyRange{RigctldRadioLink::kMinHz, RigctldRadioLink::kMaxHz, " Hz"};
// A tuning step from 0 (rigctld's "not set") to 1 MHz.
constexpr input::NumberRange kStepRange{0, 1e6, " Hz"};
// Hamlib's passband: -1 keeps the radio's, 0 asks for the mode's default.
constexpr int kMinPassbandHz = -1;
constexpr int kMaxPassbandHz = 1000000;
constexpr qsizetype kMaxModeChars = 16;

// Whole hertz: what every radio takes, and what rigctld reads back.
QString hzText(double hz)
{
    return QString::number(qint64(std::llround(hz)));
}

// "RPRT -9 (command rejected)", for a refusal.
QString refusalText(int code)
{
    const char *text = protocol::hamlibErrorText(code);
    return text ? QStringLiteral("RPRT %1 (%2)").arg(code).arg(QString::fromLatin1(text))
                : QStringLiteral("RPRT %1 (a code Hamlib does not define)").arg(code);
}

// A mode goes on the wire as one token: letters and digits only, so no
// space or line end can add an argument or a command of its own.
bool isModeToken(const QString &mode)
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

RigctldRadioLink::RigctldRadioLink(QString uri, QString host, quint16 port, QObject *parent)
    : RadioLink(parent), m_uri(std::move(uri)), m_host(std::move(host)), m_port(port)
{
    // Qt's own buffer stays small too: a peer that never sends a line end
    // fills it, and onReadyRead() closes the link then.
    m_socket.setReadBufferSize(4 * kMaxLineBytes);
    connect(&m_socket, &QTcpSocket::connected, this, &RigctldRadioLink::onConnected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &RigctldRadioLink::onSocketError);
    connect(&m_socket, &QTcpSocket::readyRead, this, &RigctldRadioLink::onReadyRead);
    connect(&m_pacer, &CommandPacer::ready, this, &RigctldRadioLink::send);
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, &RigctldRadioLink::onDeadline);
}

RigctldRadioLink::~RigctldRadioLink()
{
    // The socket outlives the pacer and the timer (members go in reverse):
    // nothing it says while it closes may reach them.
    m_socket.disconnect(this);
}

void RigctldRadioLink::open()
{
    m_pacer.clear();
    m_reply.reset();
    m_socket.abort();
    m_connected = false;
    // Each connection starts knowing nothing of the radio.
    m_receiveRead.reset();
    m_peerForm = RigctldReply::Form::Either;
    m_splitOn = false;
    m_vfoMode = false;
    m_latencyMs = 0;
    m_tuningStepHz = 1.0;
    setState(State::Opening, tr("%1: connecting to %2:%3").arg(m_uri, m_host).arg(m_port));
    m_deadline.start(kConnectTimeoutMs);
    m_socket.connectToHost(m_host, m_port);
}

void RigctldRadioLink::close()
{
    if (m_state == State::Closed)
        return;
    m_state = State::Closed;
    m_pacer.clear();
    m_reply.reset();
    m_deadline.stop();
    if (m_socket.state() == QAbstractSocket::ConnectedState) {
        // `q` tells rigctld this client is done, as Hamlib's own client says it.
        m_socket.write("q\n");
        emit commandSent(QStringLiteral("q"));
    }
    m_socket.disconnectFromHost();
    emit stateChanged(State::Closed, tr("%1: closed").arg(m_uri));
}

void RigctldRadioLink::setState(State state, const QString &detail)
{
    m_state = state;
    emit stateChanged(state, detail);
}

void RigctldRadioLink::fail(const QString &reason)
{
    if (m_state == State::Closed)
        return;
    const std::optional<PacedCommand> pending = m_pacer.inFlight();
    m_state = State::Closed;
    m_pacer.clear();
    m_reply.reset();
    m_deadline.stop();
    m_socket.abort();
    if (pending)
        emit commandFailed(pending->text, reason);
    emit stateChanged(State::Closed, reason);
}

// --- What the owner asks ---------------------------------------------------

bool RigctldRadioLink::acceptFrequency(const QString &command, double hz)
{
    QString why;
    if (input::checkNumber(hz, kFrequencyRange, &why))
        return true;
    emit commandFailed(QStringLiteral("%1 %2").arg(command).arg(hz), tr("not sent: %1").arg(why));
    return false;
}

void RigctldRadioLink::submit(CommandKind kind, Exchange exchange, const QString &text)
{
    if (m_state != State::Open) {
        emit commandFailed(text, tr("not sent: %1 is not open").arg(m_uri));
        return;
    }
    m_pacer.submit({kind, text, int(exchange)});
}

QString RigctldRadioLink::setVfoLayout(VfoLayout layout)
{
    m_layout = layout; // checked at the next opening, when VFO mode is known
    return {};
}

QString RigctldRadioLink::line(const char *verb, Path path, const QString &arguments) const
{
    QString text = QLatin1Char('+') + QLatin1String(verb);
    if (m_vfoMode) {
        const bool mainSub = m_layout == VfoLayout::MainSub;
        text += QLatin1Char(' ')
                + (mainSub ? (path == Path::Receive ? QStringLiteral("Sub") : QStringLiteral("Main"))
                           : QStringLiteral("VFOA")); // split commands name the receive VFO
    }
    if (!arguments.isEmpty())
        text += QLatin1Char(' ') + arguments;
    return text;
}

void RigctldRadioLink::setReceiveHz(double hz)
{
    if (acceptFrequency(QStringLiteral("+F"), hz))
        submit(CommandKind::ReceiveFrequency, Exchange::SetReceive, line("F", Path::Receive, hzText(hz)));
}

void RigctldRadioLink::setTransmitHz(double hz)
{
    if (!acceptFrequency(QStringLiteral("+I"), hz))
        return;
    if (m_layout == VfoLayout::MainSub)
        submit(CommandKind::TransmitFrequency, Exchange::SetTransmit, line("F", Path::Transmit, hzText(hz)));
    else
        submit(CommandKind::TransmitFrequency, Exchange::SetTransmit, line("I", Path::Transmit, hzText(hz)));
}

void RigctldRadioLink::setSplit(bool on)
{
    if (m_layout == VfoLayout::MainSub)
        return; // Main and Sub are the two paths already: no split
    if (on)
        submit(CommandKind::Split, Exchange::SetSplitOn, line("S", Path::Receive, QStringLiteral("1 VFOB")));
    else
        submit(CommandKind::Split, Exchange::SetSplitOff, line("S", Path::Receive, QStringLiteral("0 VFOA")));
}

void RigctldRadioLink::setMode(const QString &mode, int passbandHz)
{
    submitMode(CommandKind::Mode, Exchange::SetMode, line("M", Path::Receive), mode, passbandHz);
}

void RigctldRadioLink::setTransmitMode(const QString &mode, int passbandHz)
{
    // With Main/Sub the transmit VFO's own mode; with split, the split mode.
    if (m_layout == VfoLayout::MainSub)
        submitMode(CommandKind::TransmitMode, Exchange::SetTransmitMode, line("M", Path::Transmit), mode, passbandHz);
    else
        submitMode(CommandKind::TransmitMode, Exchange::SetTransmitMode, line("X", Path::Transmit), mode, passbandHz);
}

void RigctldRadioLink::submitMode(CommandKind kind, Exchange exchange, const QString &verb, const QString &mode,
                                  int passbandHz)
{
    const QString command = QStringLiteral("%1 %2 %3").arg(verb, mode).arg(passbandHz);
    if (!isModeToken(mode)) {
        emit commandFailed(input::loggableText(command, 60),
                           tr("not sent: a mode is a Hamlib mode name of letters and digits (USB, FM, PKTUSB)"));
        return;
    }
    if (passbandHz < kMinPassbandHz || passbandHz > kMaxPassbandHz) {
        emit commandFailed(command, tr("not sent: a passband is from %1 to %2 Hz (0: the mode's default)")
                                        .arg(kMinPassbandHz)
                                        .arg(kMaxPassbandHz));
        return;
    }
    submit(kind, exchange, command);
}

void RigctldRadioLink::readFrequencies()
{
    submit(CommandKind::Read, Exchange::ReadReceive, line("f", Path::Receive));
}

// --- The wire -------------------------------------------------------------

RigctldReply RigctldRadioLink::replyFor(Exchange exchange, RigctldReply::Form form) const
{
    const bool mainSub = m_layout == VfoLayout::MainSub; // the transmit path is Main's own frequency and mode
    // What rigctld echoes for each command in the extended form, and the
    // record a get answers with (the rigctld manual, "Extended Response
    // Protocol"; seen on the wire from rigctld 4.5.4).
    switch (exchange) {
    case Exchange::OpeningVfoMode: // answered in a line of its own (takeVfoModeAnswer)
    case Exchange::OpeningRead:
    case Exchange::ReadReceive:
        return RigctldReply("get_freq", "Frequency", form);
    case Exchange::ReadTransmit:
        return mainSub ? RigctldReply("get_freq", "Frequency", form)
                       : RigctldReply("get_split_freq", "TX Frequency", form);
    case Exchange::OpeningStep:
        return RigctldReply("get_ts", "Tuning Step", form);
    case Exchange::OpeningSplit:
        return RigctldReply("get_split_vfo", "Split", form);
    case Exchange::OpeningLatency:
    case Exchange::SetReceive:
        return RigctldReply("set_freq", {}, form);
    case Exchange::SetTransmit:
        return RigctldReply(mainSub ? "set_freq" : "set_split_freq", {}, form);
    case Exchange::SetSplitOn:
    case Exchange::SetSplitOff:
        return RigctldReply("set_split_vfo", {}, form);
    case Exchange::SetMode:
        return RigctldReply("set_mode", {}, form);
    case Exchange::SetTransmitMode:
        return RigctldReply(mainSub ? "set_mode" : "set_split_mode", {}, form);
    }
    Q_UNREACHABLE();
}

void RigctldRadioLink::send(const PacedCommand &command)
{
    if (Exchange(command.tag) == Exchange::OpeningVfoMode)
        m_reply.reset(); // its answer is a line of its own: takeVfoModeAnswer()
    else
        m_reply = std::make_unique<RigctldReply>(replyFor(Exchange(command.tag), m_peerForm));
    m_sentAt.start();
    m_deadline.start(m_replyTimeoutMs);
    m_socket.write(command.text.toLatin1() + '\n');
    emit commandSent(command.text);
}

void RigctldRadioLink::onConnected()
{
    m_connected = true;
    m_deadline.stop();
    // Small command lines must leave at once, not wait for Nagle.
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_pacer.submit({CommandKind::Read, QStringLiteral("+\\chk_vfo"), int(Exchange::OpeningVfoMode)});
}

void RigctldRadioLink::onSocketError()
{
    if (m_state == State::Closed)
        return;
    if (m_socket.error() == QAbstractSocket::RemoteHostClosedError)
        fail(tr("%1: rigctld closed the connection").arg(m_uri));
    else if (!m_connected)
        fail(tr("%1: cannot connect to %2:%3: %4").arg(m_uri, m_host).arg(m_port).arg(m_socket.errorString()));
    else
        fail(tr("%1: %2").arg(m_uri, m_socket.errorString()));
}

void RigctldRadioLink::onDeadline()
{
    if (!m_connected) {
        fail(tr("%1: no connection to %2:%3 within %4 s").arg(m_uri, m_host).arg(m_port).arg(kConnectTimeoutMs / 1000));
        return;
    }
    const QString command = m_pacer.inFlight() ? m_pacer.inFlight()->text : QString();
    fail(tr("%1: rigctld did not answer '%2' within %3 s").arg(m_uri, command).arg(m_replyTimeoutMs / 1000.0));
}

void RigctldRadioLink::onReadyRead()
{
    while (m_state != State::Closed) {
        if (!m_socket.canReadLine()) {
            if (m_socket.bytesAvailable() > kMaxLineBytes)
                fail(tr("%1: rigctld sent a line over %2 bytes").arg(m_uri).arg(kMaxLineBytes));
            return;
        }
        QByteArray line = m_socket.readLine(kMaxLineBytes + 1);
        if (!line.endsWith('\n')) {
            fail(tr("%1: rigctld sent a line over %2 bytes").arg(m_uri).arg(kMaxLineBytes));
            return;
        }
        line.chop(1);
        takeLine(line);
    }
}

void RigctldRadioLink::takeVfoModeAnswer(QByteArrayView answer)
{
    // rigctld 4.5 answers `ChkVFO: 1` (older ones `CHKVFO 1`, the default
    // form a bare `1`); a program that speaks rigctld's protocol without
    // knowing the command refuses it (`RPRT -11`), and is not in VFO mode.
    QByteArray text = answer.trimmed().toByteArray();
    for (const QByteArrayView prefix : {QByteArrayView("ChkVFO:"), QByteArrayView("CHKVFO")}) {
        if (text.startsWith(prefix))
            text = text.mid(prefix.size()).trimmed();
    }
    if (text == "1" || text == "0") {
        m_vfoMode = text == "1";
    } else if (!text.startsWith("RPRT ")) {
        fail(tr("%1: unreadable answer to \\chk_vfo: '%2'")
                 .arg(m_uri, input::loggableText(QString::fromLatin1(answer), 40)));
        return;
    }
    m_deadline.stop();
    if (m_layout == VfoLayout::MainSub && !m_vfoMode) {
        fail(tr("%1: receiving on Sub and transmitting on Main needs rigctld in VFO mode: start it with -o "
                "(--vfo)")
                 .arg(m_uri));
        return;
    }
    m_pacer.finished(PacedCommand{CommandKind::Read, line("f", Path::Receive), int(Exchange::OpeningRead)});
}

void RigctldRadioLink::takeLine(QByteArrayView line)
{
    const std::optional<PacedCommand> &inFlight = m_pacer.inFlight();
    if (!m_reply && inFlight && Exchange(inFlight->tag) == Exchange::OpeningVfoMode) {
        takeVfoModeAnswer(line);
        return;
    }
    if (!m_reply) {
        fail(tr("%1: rigctld sent '%2', which nothing asked for")
                 .arg(m_uri, input::loggableText(QString::fromLatin1(line), 40)));
        return;
    }
    switch (m_reply->take(line)) {
    case RigctldReply::Status::Incomplete:
        return;
    case RigctldReply::Status::Broken:
        fail(tr("%1: unreadable answer from rigctld: %2").arg(m_uri, m_reply->problem()));
        return;
    case RigctldReply::Status::Complete:
        break;
    }
    m_deadline.stop();
    const std::unique_ptr<RigctldReply> reply = std::move(m_reply);
    // A peer keeps to the form it first answered in; from now on another
    // form is a line out of place.
    if (m_peerForm == RigctldReply::Form::Either)
        m_peerForm = reply->extended() ? RigctldReply::Form::Extended : RigctldReply::Form::Default;
    const PacedCommand command = *m_pacer.inFlight();
    finishExchange(command, *reply);
}

void RigctldRadioLink::finishExchange(const PacedCommand &command, const RigctldReply &reply)
{
    const Exchange exchange = Exchange(command.tag);
    const bool refused = reply.code() != 0;
    QString failure; // for commandFailed(): why this command did nothing
    std::optional<PacedCommand> next;
    std::optional<RadioFrequencies> read;
    bool opened = false;

    // A value the answer must hold: a number in `range`; else `failure` says why.
    auto valueIn = [&](const input::NumberRange &range) -> std::optional<double> {
        if (!reply.value()) {
            failure = tr("the answer held no value");
            return std::nullopt;
        }
        QString why;
        const std::optional<double> v = input::numberIn(*reply.value(), range, &why);
        if (!v)
            failure = tr("unusable answer: %1").arg(why);
        return v;
    };

    if (refused)
        failure = tr("refused: %1").arg(refusalText(reply.code()));

    switch (exchange) {
    case Exchange::OpeningVfoMode:
        break; // answered by takeVfoModeAnswer(), never through here
    case Exchange::OpeningRead: {
        const std::optional<double> hz = refused ? std::nullopt : valueIn(kFrequencyRange);
        if (!hz) {
            fail(tr("%1: cannot read the frequency: %2").arg(m_uri, failure));
            return;
        }
        m_receiveRead = hz;
        next = PacedCommand{CommandKind::ReceiveFrequency, line("F", Path::Receive, hzText(*hz)),
                            int(Exchange::OpeningLatency)};
        break;
    }
    case Exchange::OpeningLatency:
        if (!refused)
            m_latencyMs = int(m_sentAt.elapsed());
        next = PacedCommand{CommandKind::Read, line("n", Path::Receive), int(Exchange::OpeningStep)};
        break;
    case Exchange::OpeningStep:
        // A backend without get_ts refuses it (RPRT -11): the step is then
        // not known, which is no fault of the link.
        if (refused) {
            failure.clear();
        } else if (const std::optional<double> step = valueIn(kStepRange)) {
            m_tuningStepHz = *step > 0 ? *step : 1.0; // 0: rigctld has none set
        }
        // Whether split is on already (the operator's, or a pass before):
        // reads then ask the transmit frequency too. Asked only of a peer
        // that answers in the extended form: the default form's two bare
        // lines could not be told from a stray one.
        if (m_peerForm == RigctldReply::Form::Extended && m_layout == VfoLayout::Split)
            next = PacedCommand{CommandKind::Read, line("s", Path::Receive), int(Exchange::OpeningSplit)};
        else
            opened = true;
        break;
    case Exchange::OpeningSplit:
        failure.clear(); // a backend without get_split_vfo: split is then taken as off
        m_splitOn = !refused && reply.value() && reply.value()->trimmed() == QLatin1String("1");
        opened = true;
        break;
    case Exchange::SetSplitOn:
        if (!refused)
            m_splitOn = true;
        break;
    case Exchange::SetSplitOff:
        if (!refused)
            m_splitOn = false;
        break;
    case Exchange::SetReceive:
    case Exchange::SetTransmit:
    case Exchange::SetMode:
    case Exchange::SetTransmitMode:
        break;
    case Exchange::ReadReceive: {
        const std::optional<double> hz = refused ? std::nullopt : valueIn(kFrequencyRange);
        if (!hz)
            break;
        if (m_layout == VfoLayout::MainSub) {
            m_receiveRead = hz;
            next = PacedCommand{CommandKind::Read, line("f", Path::Transmit), int(Exchange::ReadTransmit)};
        } else if (m_splitOn) {
            m_receiveRead = hz;
            next = PacedCommand{CommandKind::Read, line("i", Path::Transmit), int(Exchange::ReadTransmit)};
        } else {
            read = RadioFrequencies{hz, std::nullopt};
        }
        break;
    }
    case Exchange::ReadTransmit: {
        const std::optional<double> hz = refused ? std::nullopt : valueIn(kFrequencyRange);
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

void RigctldRadioLink::becomeOpen()
{
    if (m_state != State::Opening)
        return; // closed by a handler of the signals before
    // The frequency as the operator reads it off the dial; none when the
    // first reading had none.
    const QString where = m_receiveRead ? tr(" at %1").arg(groupedMegahertz(*m_receiveRead)) : QString();
    setState(State::Open, tr("%1: open%2; a set answered in %3 ms").arg(m_uri, where).arg(m_latencyMs));
}

} // namespace slew::radio
