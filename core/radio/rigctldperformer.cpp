// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigctldperformer.h"

#include "input/logtext.h"
#include "protocol/hamliberrors.h"
#include "radiolimits.h"

namespace slew::radio {

namespace {

// "RPRT -9 (command rejected)", for a refusal.
QString refusalText(int code)
{
    const char *text = protocol::hamlibErrorText(code);
    return text ? QStringLiteral("RPRT %1 (%2)").arg(code).arg(QString::fromLatin1(text))
                : QStringLiteral("RPRT %1 (a code Hamlib does not define)").arg(code);
}

} // namespace

RigctldPerformer::RigctldPerformer(QString host, quint16 port, QObject *parent)
    : ExchangePerformer(parent), m_host(std::move(host)), m_port(port)
{
    // Qt's own buffer stays small too: a peer that never sends a line end
    // fills it, and onReadyRead() gives up then.
    m_socket.setReadBufferSize(4 * kMaxLineBytes);
    connect(&m_socket, &QTcpSocket::connected, this, &RigctldPerformer::onConnected);
    connect(&m_socket, &QTcpSocket::errorOccurred, this, &RigctldPerformer::onSocketError);
    connect(&m_socket, &QTcpSocket::readyRead, this, &RigctldPerformer::onReadyRead);
    m_deadline.setSingleShot(true);
    connect(&m_deadline, &QTimer::timeout, this, &RigctldPerformer::onDeadline);
}

RigctldPerformer::~RigctldPerformer()
{
    // The socket outlives the timer (members go in reverse): nothing it
    // says while it closes may reach it.
    m_socket.disconnect(this);
}

QString RigctldPerformer::reaching() const
{
    return tr("connecting to %1:%2").arg(m_host).arg(m_port);
}

void RigctldPerformer::open(VfoLayout layout)
{
    m_socket.abort();
    m_reply.reset();
    // Each connection starts knowing nothing of the peer.
    m_layout = layout;
    m_vfoMode = false;
    m_peerForm = RigctldReply::Form::Either;
    m_phase = Phase::Connecting;
    m_deadline.start(limits::kConnectTimeoutMs);
    m_socket.connectToHost(m_host, m_port);
}

void RigctldPerformer::close()
{
    const bool connected = m_socket.state() == QAbstractSocket::ConnectedState;
    m_phase = Phase::Idle;
    m_reply.reset();
    m_deadline.stop();
    if (connected) {
        // `q` tells rigctld this client is done, as Hamlib's own client says it.
        m_socket.write("q\n");
        emit said(QStringLiteral("q"));
    }
    m_socket.disconnectFromHost();
}

void RigctldPerformer::abort()
{
    m_phase = Phase::Idle;
    m_reply.reset();
    m_deadline.stop();
    m_socket.abort();
}

void RigctldPerformer::lose(const QString &reason)
{
    if (m_phase == Phase::Idle)
        return;
    abort();
    emit lost(reason);
}

// --- Commands as lines -------------------------------------------------------

QString RigctldPerformer::line(const char *verb, RadioPath path, const QString &arguments) const
{
    QString text = QLatin1Char('+') + QLatin1String(verb);
    if (m_vfoMode) {
        const bool mainSub = m_layout == VfoLayout::MainSub;
        text += QLatin1Char(' ')
                + (mainSub ? (path == RadioPath::Receive ? QStringLiteral("Sub") : QStringLiteral("Main"))
                           : QStringLiteral("VFOA")); // split commands name the receive VFO
    }
    if (!arguments.isEmpty())
        text += QLatin1Char(' ') + arguments;
    return text;
}

QString RigctldPerformer::text(const RadioCommand &command) const
{
    // With Main/Sub the transmit path is Main's own frequency and mode;
    // with split, the split VFO's (`I`, `i`, `X`).
    const bool splitVfo = command.path == RadioPath::Transmit && m_layout == VfoLayout::Split;
    using Call = RadioCommand::Call;
    switch (command.call) {
    case Call::ReadFrequency:
        return line(splitVfo ? "i" : "f", command.path);
    case Call::SetFrequency:
        return line(splitVfo ? "I" : "F", command.path, commandHzText(command.hz));
    case Call::SetMode:
        return line(splitVfo ? "X" : "M", command.path, QStringLiteral("%1 %2").arg(command.mode).arg(command.passbandHz));
    case Call::SetSplit:
        return line("S", RadioPath::Receive, command.on ? QStringLiteral("1 VFOB") : QStringLiteral("0 VFOA"));
    case Call::ReadSplit:
        return line("s", RadioPath::Receive);
    case Call::ReadStep:
        return line("n", RadioPath::Receive);
    }
    Q_UNREACHABLE();
}

RigctldReply RigctldPerformer::replyFor(const RadioCommand &command) const
{
    // What rigctld echoes for each command in the extended form, and the
    // record a get answers with (the rigctld manual, "Extended Response
    // Protocol"; seen on the wire from rigctld 4.5.4).
    const bool splitVfo = command.path == RadioPath::Transmit && m_layout == VfoLayout::Split;
    using Call = RadioCommand::Call;
    switch (command.call) {
    case Call::ReadFrequency:
        return splitVfo ? RigctldReply("get_split_freq", "TX Frequency", m_peerForm)
                        : RigctldReply("get_freq", "Frequency", m_peerForm);
    case Call::SetFrequency:
        return RigctldReply(splitVfo ? "set_split_freq" : "set_freq", {}, m_peerForm);
    case Call::SetMode:
        return RigctldReply(splitVfo ? "set_split_mode" : "set_mode", {}, m_peerForm);
    case Call::SetSplit:
        return RigctldReply("set_split_vfo", {}, m_peerForm);
    case Call::ReadSplit:
        return RigctldReply("get_split_vfo", "Split", m_peerForm);
    case Call::ReadStep:
        return RigctldReply("get_ts", "Tuning Step", m_peerForm);
    }
    Q_UNREACHABLE();
}

void RigctldPerformer::perform(const RadioCommand &command)
{
    m_reply = std::make_unique<RigctldReply>(replyFor(command));
    m_socket.write(text(command).toLatin1() + '\n');
}

// --- The wire -------------------------------------------------------------

void RigctldPerformer::onConnected()
{
    // Small command lines must leave at once, not wait for Nagle.
    m_socket.setSocketOption(QAbstractSocket::LowDelayOption, 1);
    m_phase = Phase::AskingVfoMode;
    m_deadline.start(limits::kReplyTimeoutMs);
    const QString ask = QStringLiteral("+\\chk_vfo");
    m_socket.write(ask.toLatin1() + '\n');
    emit said(ask);
}

void RigctldPerformer::onSocketError()
{
    if (m_phase == Phase::Idle)
        return;
    if (m_socket.error() == QAbstractSocket::RemoteHostClosedError)
        lose(tr("rigctld closed the connection"));
    else if (m_phase == Phase::Connecting)
        lose(tr("cannot connect to %1:%2: %3").arg(m_host).arg(m_port).arg(m_socket.errorString()));
    else
        lose(m_socket.errorString());
}

void RigctldPerformer::onDeadline()
{
    if (m_phase == Phase::Connecting)
        lose(tr("no connection to %1:%2 within %3 s").arg(m_host).arg(m_port).arg(limits::kConnectTimeoutMs / 1000));
    else
        lose(tr("rigctld did not answer '+\\chk_vfo' within %1 s").arg(limits::kReplyTimeoutMs / 1000));
}

void RigctldPerformer::onReadyRead()
{
    while (m_phase != Phase::Idle) {
        if (!m_socket.canReadLine()) {
            if (m_socket.bytesAvailable() > kMaxLineBytes)
                lose(tr("rigctld sent a line over %1 bytes").arg(kMaxLineBytes));
            return;
        }
        QByteArray line = m_socket.readLine(kMaxLineBytes + 1);
        if (!line.endsWith('\n')) {
            lose(tr("rigctld sent a line over %1 bytes").arg(kMaxLineBytes));
            return;
        }
        line.chop(1);
        takeLine(line);
    }
}

void RigctldPerformer::takeVfoModeAnswer(QByteArrayView answer)
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
        lose(tr("unreadable answer to \\chk_vfo: '%1'").arg(input::loggableText(QString::fromLatin1(answer), 40)));
        return;
    }
    m_deadline.stop();
    if (m_layout == VfoLayout::MainSub && !m_vfoMode) {
        lose(tr("receiving on Sub and transmitting on Main needs rigctld in VFO mode: start it with -o (--vfo)"));
        return;
    }
    m_phase = Phase::Ready;
    emit opened();
}

void RigctldPerformer::takeLine(QByteArrayView line)
{
    if (m_phase == Phase::AskingVfoMode) {
        takeVfoModeAnswer(line);
        return;
    }
    if (!m_reply) {
        lose(tr("rigctld sent '%1', which nothing asked for").arg(input::loggableText(QString::fromLatin1(line), 40)));
        return;
    }
    switch (m_reply->take(line)) {
    case RigctldReply::Status::Incomplete:
        return;
    case RigctldReply::Status::Broken:
        lose(tr("unreadable answer from rigctld: %1").arg(m_reply->problem()));
        return;
    case RigctldReply::Status::Complete:
        break;
    }
    const std::unique_ptr<RigctldReply> reply = std::move(m_reply);
    // A peer keeps to the form it first answered in; from now on another
    // form is a line out of place.
    if (m_peerForm == RigctldReply::Form::Either)
        m_peerForm = reply->extended() ? RigctldReply::Form::Extended : RigctldReply::Form::Default;
    RadioAnswer answer;
    answer.code = reply->code();
    if (answer.code != 0)
        answer.why = tr("refused: %1").arg(refusalText(answer.code));
    answer.value = reply->value();
    emit answered(answer);
}

} // namespace slew::radio
