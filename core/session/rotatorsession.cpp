#include "rotatorsession.h"

#include "protocol/encoder.h"
#include "transport/link.h"
#include "transport/linkfactory.h"

#include <QDateTime>
#include <QIODevice>

#include <algorithm>
#include <cmath>

namespace slew::session {

using protocol::Dialect;
using protocol::Message;
using protocol::Op;

namespace {

constexpr int kMaxReconnectDelayMs = 30000;
constexpr qint64 kEchoWindowMs = 1000;
constexpr int kTelemetryGiveUpAfter = 3; // a query unanswered this often is not polled again
constexpr int kMaxRawLine = 200;

QString printable(const QByteArray &line)
{
    return QString::fromLatin1(line).trimmed();
}

// A token the controller has no reason to send: a command, or a query form.
bool isCommandOnly(Op op)
{
    switch (op) {
    case Op::MoveLeft:
    case Op::MoveRight:
    case Op::MoveUp:
    case Op::MoveDown:
    case Op::StopAzimuth:
    case Op::StopElevation:
    case Op::Reset:
    case Op::Park:
    case Op::ConfigWrite:
    case Op::SetOutput:
    case Op::Aos:
    case Op::Los:
        return true;
    default:
        return false;
    }
}

} // namespace

RotatorSession::RotatorSession(QObject *parent) : QObject(parent), m_queue(m_options.maxQueue)
{
    qRegisterMetaType<Telemetry>();
    qRegisterMetaType<Capabilities>();
    qRegisterMetaType<StatusWord>();
    m_clock.start();

    m_replyTimer.setSingleShot(true);
    connect(&m_replyTimer, &QTimer::timeout, this, &RotatorSession::onReplyTimeout);
    m_reconnectTimer.setSingleShot(true);
    connect(&m_reconnectTimer, &QTimer::timeout, this, &RotatorSession::openLink);
    m_staleTimer.setSingleShot(true);
    connect(&m_staleTimer, &QTimer::timeout, this, &RotatorSession::onStale);
    connect(&m_pollTimer, &QTimer::timeout, this, &RotatorSession::poll);
    setProfile(m_profile);
}

RotatorSession::~RotatorSession()
{
    m_wantConnected = false;
    if (m_link) {
        m_link->disconnect(this);
        m_link->device()->disconnect(this);
        m_link->close();
    }
}

void RotatorSession::setProfile(const model::RotatorProfile &profile)
{
    m_profile = profile;
    m_parser.setDialect(profile.dialect);
    m_pollTimer.setInterval(1000 / std::clamp(profile.pollHz, 1, 50));
    const int pollPeriod = m_pollTimer.interval();
    m_staleTimer.setInterval(std::max(1500, 3 * pollPeriod + m_options.replyTimeoutMs * (m_options.retries + 1)));
    emit profileChanged();
}

void RotatorSession::setOptions(const Options &options)
{
    m_options = options;
    m_queue.setCapacity(options.maxQueue);
    setProfile(m_profile);
}

void RotatorSession::setPolling(bool enabled)
{
    m_pollingEnabled = enabled;
}

// --- Connection -------------------------------------------------------------

void RotatorSession::setState(State s, const QString &detail)
{
    m_state = s;
    emit stateChanged(s, detail);
}

void RotatorSession::connectTo(const QString &uri)
{
    m_wantConnected = false;
    m_reconnectTimer.stop();
    dropLink();
    m_uri = uri;
    m_wantConnected = true;
    m_reconnectAttempt = 0;
    openLink();
}

void RotatorSession::disconnectFromRotator()
{
    const bool had = m_link != nullptr || m_state != State::Disconnected;
    m_wantConnected = false;
    m_reconnectTimer.stop();
    dropLink();
    if (had)
        setState(State::Disconnected, tr("disconnected"));
}

void RotatorSession::openLink()
{
    transport::LinkResult made = transport::createLink(m_uri);
    if (!made.link) {
        m_wantConnected = false;
        setState(State::Disconnected, made.error);
        emit errorOccurred(made.error);
        return;
    }
    m_link = std::move(made.link);
    connect(m_link.get(), &transport::Link::opened, this, &RotatorSession::onLinkOpened);
    connect(m_link.get(), &transport::Link::failed, this, &RotatorSession::onLinkDown);
    connect(m_link.get(), &transport::Link::lost, this, &RotatorSession::onLinkDown);
    connect(m_link->device(), &QIODevice::readyRead, this, &RotatorSession::onReadyRead);
    connect(m_link.get(), &transport::Link::notice, this, &RotatorSession::errorOccurred);
    connect(m_link.get(), &transport::Link::limitsReported, this,
            [this](double azMin, double azMax, double elMin, double elMax) {
                m_reportedLimits = model::RotatorLimits{azMin, azMax, elMin, elMax};
            });
    setState(m_reconnectAttempt > 0 ? State::Reconnecting : State::Connecting, tr("opening %1").arg(m_uri));
    m_link->open();
}

void RotatorSession::onLinkOpened()
{
    m_parser.reset();
    m_deviceEchoes = false;
    m_reconnectAttempt = 0;
    m_failedPolls = 0;
    m_pollCount = 0;
    setState(State::Connected, tr("connected to %1").arg(m_uri));
    startProbe();
    m_pollTimer.start();
}

void RotatorSession::onLinkDown(const QString &reason)
{
    // Whether it never opened or went away, the way on is the same: retry
    // when the operator asked for it, else stay disconnected with the reason.
    emit errorOccurred(reason);
    if (m_wantConnected && m_options.autoReconnect) {
        scheduleReconnect(reason);
        return;
    }
    m_wantConnected = false;
    dropLink(reason);
    setState(State::Disconnected, reason);
}

void RotatorSession::scheduleReconnect(const QString &reason)
{
    dropLink(reason);
    const int delay = std::min(kMaxReconnectDelayMs, 500 << std::min(m_reconnectAttempt, 6));
    ++m_reconnectAttempt;
    setState(State::Reconnecting, tr("%1; retrying in %2 s").arg(reason).arg(delay / 1000.0, 0, 'f', 1));
    m_reconnectTimer.start(delay);
}

void RotatorSession::dropLink(const QString &reason)
{
    m_pollTimer.stop();
    m_replyTimer.stop();
    m_staleTimer.stop();
    m_onWire = false;
    m_jogSpeed = {0.0, 0.0};
    if (m_link) {
        m_link->disconnect(this);
        m_link->device()->disconnect(this);
        m_link->close();
        // Not deleted here: we may be inside one of its signals.
        m_link.release()->deleteLater();
    }
    // Nothing is dropped silently: every waiting request hears why.
    const QString why = reason.isEmpty() ? tr("link closed") : reason;
    m_queue.failAll(why);
    if (!m_stale && hasPosition()) {
        m_stale = true;
        emit positionChanged(m_az, m_el, true);
    }
    m_stale = true;
    m_caps = Capabilities{};
    m_reportedLimits.reset();
    emit capabilitiesChanged(m_caps);
}

// --- Receiving --------------------------------------------------------------

void RotatorSession::onReadyRead()
{
    if (!m_link)
        return;
    const QByteArray bytes = m_link->device()->readAll();
    if (bytes.isEmpty())
        return;
    emit bytesReceived(bytes);
    m_parser.feed(bytes, [this](const Message &m) { apply(m); });
}

bool RotatorSession::isEcho(const Message &m)
{
    // Unmistakable echoes: a command, or a query form, coming back. Seeing one
    // tells us this controller echoes what it hears.
    if (isCommandOnly(m.op)
        || (m.op != Op::Alarm && m.op != Op::Invalid && !m.hasValue && m.text.isEmpty())) {
        m_deviceEchoes = true;
        return true;
    }
    if (m.op == Op::VelocityLeft || m.op == Op::VelocityRight || m.op == Op::VelocityUp
        || m.op == Op::VelocityDown)
        return true; // a controller reports speed in IP7/IP8, never as VL..VD
    // A set position coming back reads exactly like a position report, so it
    // is only taken for an echo from a controller known to echo, and only
    // when it repeats what was sent within the last second.
    if (!m_deviceEchoes || (m.op != Op::Azimuth && m.op != Op::Elevation))
        return false;
    const qint64 now = m_clock.elapsed();
    for (const Sent &s : m_sent) {
        if (now - s.atMs <= kEchoWindowMs && s.message.op == m.op && s.message.hasValue
            && std::abs(s.message.value - m.value) < 1e-9)
            return true;
    }
    return false;
}

void RotatorSession::apply(const Message &m)
{
    if (isEcho(m)) {
        ++m_echoesIgnored;
        return;
    }
    switch (m.op) {
    case Op::Azimuth:
        m_az = m.value;
        m_azFresh = true;
        if (m.lineEnd || m_elFresh)
            applyPosition();
        break;
    case Op::Elevation:
        m_el = m.value;
        m_elFresh = true;
        applyPosition();
        break;
    case Op::Status:
        if (!m_status.valid || m_status.raw != quint16(m.value)) {
            m_status = StatusWord{quint16(m.value), true};
            emit statusChanged(m_status);
        }
        break;
    case Op::ErrorFlags:
        if (m_errorFlags != int(m.value)) {
            m_errorFlags = int(m.value);
            emit errorFlagsChanged(m_errorFlags);
        }
        break;
    case Op::ReadInput:
        if (m.hasValue)
            applyInput(m.index, m.value);
        break;
    case Op::ConfigRead:
    case Op::ConfigValue:
        applyConfig(m.index, QString::fromLatin1(m.text.view().toByteArray()), m.hasValue, m.value);
        break;
    case Op::Version:
        m_version = QString::fromLatin1(m.text.view().toByteArray());
        emit versionChanged(m_version);
        break;
    case Op::Encoders:
        emit encodersChanged(m.encoders[0], m.encoders[1], m.encoders[2], m.encoders[3]);
        break;
    case Op::Alarm: {
        const QString text = QString::fromLatin1(m.text.view().toByteArray());
        emit alarmReceived(text);
        emit errorOccurred(tr("controller alarm: %1").arg(text));
        if (m_onWire)
            finishFront(false, tr("the controller answered with alarm %1").arg(text));
        return;
    }
    case Op::Invalid:
        emit errorOccurred(tr("unreadable reply '%1': %2")
                               .arg(QString::fromLatin1(m.text.view().toByteArray().left(40)),
                                    QString::fromLatin1(m.reason)));
        return;
    default:
        break; // Easycomm II controllers may report UP/DN/modes; nothing to do with them
    }
    if (m_onWire && m_queue.offer(m)) {
        const Request *front = m_queue.front();
        if (front && front->complete())
            finishFront(true, {});
    }
}

void RotatorSession::applyPosition()
{
    if (!hasPosition())
        return;
    m_azFresh = m_elFresh = false;
    m_failedPolls = 0;
    m_stale = false;
    if (m_state == State::Connected)
        m_staleTimer.start();
    emit positionChanged(m_az, m_el, false);
    checkSoftLimits();
}

void RotatorSession::applyInput(int index, double value)
{
    switch (index) {
    case 0: m_telemetry.temperature = value; break;
    case 1: m_telemetry.azEndStop = int(value); break;
    case 2: m_telemetry.elEndStop = int(value); break;
    case 5: m_telemetry.azLoad = value; break;
    case 6: m_telemetry.elLoad = value; break;
    case 7: m_telemetry.azVelocity = value; break;
    case 8: m_telemetry.elVelocity = value; break;
    default: return; // IP3/IP4 repeat the position we already poll
    }
    m_telemetry.timeMs = QDateTime::currentMSecsSinceEpoch();
    emit telemetryChanged(m_telemetry);
}

void RotatorSession::applyConfig(int reg, const QString &text, bool numeric, double value)
{
    emit configValueReceived(reg, text);
    if (!numeric)
        return;
    if (reg == 10)
        m_commandedAz = value;
    else if (reg == 11)
        m_commandedEl = value;
    else
        return;
    emit commandedChanged(m_commandedAz, m_commandedEl);
}

void RotatorSession::onStale()
{
    if (!m_stale && hasPosition()) {
        m_stale = true;
        emit positionChanged(m_az, m_el, true);
    }
}

// --- Sending ----------------------------------------------------------------

bool RotatorSession::refuse(const QString &reason)
{
    emit commandRefused(reason);
    return false;
}

bool RotatorSession::requireLink()
{
    if (m_state == State::Connected && m_link && m_link->isOpen())
        return true;
    return refuse(tr("not connected to a rotator"));
}

void RotatorSession::write(const QByteArray &line)
{
    if (!m_link || line.isEmpty())
        return;
    m_link->device()->write(line);
    emit bytesSent(line);
}

void RotatorSession::rememberSent(const Message &m)
{
    m_sent[size_t(m_sentNext)] = Sent{m, m_clock.elapsed()};
    m_sentNext = (m_sentNext + 1) % int(m_sent.size());
}

bool RotatorSession::enqueue(Request r)
{
    if (m_queue.isFull()) {
        const QString reason = tr("the controller is not keeping up: %1 requests already waiting").arg(m_queue.size());
        if (r.done)
            r.done(false, reason);
        return false;
    }
    m_queue.push(std::move(r));
    sendNext();
    return true;
}

void RotatorSession::sendNext()
{
    if (m_onWire || !m_link || !m_link->isOpen())
        return;
    Request *front = m_queue.front();
    if (!front)
        return;
    front->satisfied = 0;
    m_onWire = true;
    write(front->line);
    m_replyTimer.start(m_options.replyTimeoutMs);
}

void RotatorSession::onReplyTimeout()
{
    Request *front = m_queue.front();
    if (!front || !m_onWire)
        return;
    if (--front->attemptsLeft > 0) {
        m_onWire = false;
        sendNext();
        return;
    }
    finishFront(false, tr("no answer within %1 ms").arg(m_options.replyTimeoutMs));
}

void RotatorSession::finishFront(bool ok, const QString &reason)
{
    m_replyTimer.stop();
    m_onWire = false;
    if (m_queue.isEmpty())
        return;
    Request r = m_queue.takeFront();
    if (!ok && r.purpose == RequestPurpose::Position)
        ++m_failedPolls;
    if (r.done)
        r.done(ok, reason);
    sendNext();
}

// --- Probe and polling ------------------------------------------------------

void RotatorSession::startProbe()
{
    const Dialect d = m_profile.dialect;
    m_caps = Capabilities{};
    m_caps.velocity = protocol::dialectSupports(d, Op::VelocityLeft);
    m_caps.moveCommands = protocol::dialectSupports(d, Op::MoveLeft);
    m_caps.park = protocol::dialectSupports(d, Op::Park);
    m_caps.reset = protocol::dialectSupports(d, Op::Reset);
    m_caps.stop = protocol::dialectSupports(d, Op::StopAzimuth);
    m_telemetryFailures.clear();

    struct Probe {
        Op op;
        int index;
        bool Capabilities::*flag;
    };
    const Probe probes[] = {
        {Op::Azimuth, -1, &Capabilities::positionFeedback}, {Op::Version, -1, &Capabilities::version},
        {Op::Status, -1, &Capabilities::status},            {Op::ErrorFlags, -1, &Capabilities::errors},
        {Op::ReadInput, 0, &Capabilities::inputs},          {Op::ConfigRead, 1, &Capabilities::config},
        {Op::Encoders, -1, &Capabilities::encoders},
    };
    m_probesOutstanding = 0;
    QList<Request> requests;
    for (const Probe &p : probes) {
        if (!protocol::dialectSupports(d, p.op))
            continue;
        Request r;
        r.purpose = RequestPurpose::Probe;
        if (p.op == Op::Azimuth) {
            r.line = protocol::encodeQueryPosition(d);
            r.expects = {Expectation{Op::Azimuth, -1}, Expectation{Op::Elevation, -1}};
            r.expectCount = 2;
            r.attemptsLeft = m_options.retries + 1;
        } else {
            r.line = protocol::encodeLine({Message::query(p.op, p.index)}, d);
            r.expects[0] = Expectation{p.op, p.index};
            r.expectCount = 1;
            r.attemptsLeft = 1; // a controller that lacks a command stays silent
        }
        r.done = [this, flag = p.flag](bool ok, const QString &) {
            m_caps.*flag = ok;
            if (--m_probesOutstanding == 0) {
                m_caps.probed = true;
                emit capabilitiesChanged(m_caps);
                poll();
            }
        };
        requests.append(std::move(r));
    }
    m_probesOutstanding = int(requests.size());
    if (requests.isEmpty()) {
        m_caps.probed = true; // Easycomm I: nothing to ask
        emit capabilitiesChanged(m_caps);
        return;
    }
    for (Request &r : requests)
        enqueue(std::move(r));
}

void RotatorSession::poll()
{
    if (m_state != State::Connected || !m_link || !m_link->isOpen() || !m_pollingEnabled || !m_caps.probed)
        return;
    const Dialect d = m_profile.dialect;
    if (m_caps.positionFeedback) {
        const QByteArray line = protocol::encodeQueryPosition(d);
        if (!m_queue.contains(line)) {
            Request r;
            r.line = line;
            r.expects = {Expectation{Op::Azimuth, -1}, Expectation{Op::Elevation, -1}};
            r.expectCount = 2;
            r.attemptsLeft = m_options.retries + 1;
            r.purpose = RequestPurpose::Position;
            enqueue(std::move(r));
        }
    }
    if (m_pollCount++ % std::max(1, m_options.telemetryEvery) != 0)
        return;

    auto ask = [&](Op op, int index) {
        const QByteArray line = protocol::encodeLine({Message::query(op, index)}, d);
        if (line.isEmpty() || m_queue.contains(line) || m_telemetryFailures.value(line) >= kTelemetryGiveUpAfter)
            return;
        Request r;
        r.line = line;
        r.expects[0] = Expectation{op, index};
        r.expectCount = 1;
        r.attemptsLeft = 1;
        r.purpose = RequestPurpose::Telemetry;
        r.done = [this, line](bool ok, const QString &) {
            if (ok)
                m_telemetryFailures.remove(line);
            else
                ++m_telemetryFailures[line];
        };
        enqueue(std::move(r));
    };
    if (m_caps.status)
        ask(Op::Status, -1);
    if (m_caps.errors)
        ask(Op::ErrorFlags, -1);
    if (m_caps.inputs) {
        for (int input : {0, 1, 2, 5, 6, 7, 8})
            ask(Op::ReadInput, input);
    }
    if (m_caps.config) {
        ask(Op::ConfigRead, 10);
        ask(Op::ConfigRead, 11);
    }
}

void RotatorSession::checkSoftLimits()
{
    // A velocity move runs until told otherwise; the profile's limits may be
    // tighter than the controller's own, so stop the axis at them.
    const auto &lim = m_profile.limits;
    if ((m_jogSpeed[0] > 0 && m_az >= lim.azMax) || (m_jogSpeed[0] < 0 && m_az <= lim.azMin)) {
        stop(Axes::Azimuth);
        emit errorOccurred(tr("azimuth reached the profile limit at %1°; stopped").arg(m_az, 0, 'f', 1));
    }
    if ((m_jogSpeed[1] > 0 && m_el >= lim.elMax) || (m_jogSpeed[1] < 0 && m_el <= lim.elMin)) {
        stop(Axes::Elevation);
        emit errorOccurred(tr("elevation reached the profile limit at %1°; stopped").arg(m_el, 0, 'f', 1));
    }
}

// --- Commands ---------------------------------------------------------------

bool RotatorSession::gotoPosition(double az, double el)
{
    if (!requireLink())
        return false;
    if (QString e = model::checkElevation(m_profile.limits, el); !e.isEmpty())
        return refuse(e);
    const auto choice =
        model::chooseAzimuth(m_profile.limits, az, hasPosition() ? std::optional<double>(m_az) : std::nullopt);
    if (!choice.azimuth)
        return refuse(choice.error);
    const double targetAz = *choice.azimuth;
    if (m_reportedLimits) {
        const QString outside = tr("%1 (the limits the link reports)");
        if (QString e = model::checkElevation(*m_reportedLimits, el); !e.isEmpty())
            return refuse(outside.arg(e));
        if (targetAz < m_reportedLimits->azMin - 1e-6 || targetAz > m_reportedLimits->azMax + 1e-6)
            return refuse(outside.arg(tr("azimuth %1° is outside %2°..%3°")
                                          .arg(targetAz, 0, 'f', 1)
                                          .arg(m_reportedLimits->azMin, 0, 'f', 0)
                                          .arg(m_reportedLimits->azMax, 0, 'f', 0)));
    }
    const QByteArray line = protocol::encodeSetPosition(targetAz, el, m_profile.dialect);
    rememberSent(Message::number(Op::Azimuth, std::round(targetAz * 100) / 100));
    rememberSent(Message::number(Op::Elevation, std::round(el * 100) / 100));
    m_jogSpeed = {0.0, 0.0};
    write(line);
    m_targetAz = targetAz;
    m_targetEl = el;
    emit targetChanged(targetAz, el);
    return true;
}

bool RotatorSession::gotoAxis(Axis axis, double degrees)
{
    if (!requireLink())
        return false;
    const bool az = axis == Axis::Azimuth;
    const Op op = az ? Op::Azimuth : Op::Elevation;
    const Dialect d = m_profile.dialect;
    // Easycomm I and GS-232 can only command both axes together.
    if (d == Dialect::Easycomm1 || protocol::isGs232(d)) {
        const double other = az ? (hasPosition() ? m_el : m_targetEl) : (hasPosition() ? m_az : m_targetAz);
        if (std::isnan(other))
            return refuse(tr("%1 moves both axes at once, and the other axis' position is not known yet")
                              .arg(protocol::dialectName(d)));
        return az ? gotoPosition(degrees, other) : gotoPosition(other, degrees);
    }
    double target = degrees;
    if (az) {
        const auto choice =
            model::chooseAzimuth(m_profile.limits, degrees, hasPosition() ? std::optional<double>(m_az) : std::nullopt);
        if (!choice.azimuth)
            return refuse(choice.error);
        target = *choice.azimuth;
    } else if (QString e = model::checkElevation(m_profile.limits, degrees); !e.isEmpty()) {
        return refuse(e);
    }
    if (m_reportedLimits) {
        const bool outside = az ? (target < m_reportedLimits->azMin - 1e-6 || target > m_reportedLimits->azMax + 1e-6)
                                : !model::checkElevation(*m_reportedLimits, target).isEmpty();
        if (outside)
            return refuse(tr("%1° is outside the limits the link reports").arg(target, 0, 'f', 1));
    }
    const Message m = Message::number(op, target);
    rememberSent(Message::number(op, std::round(target * 100) / 100));
    m_jogSpeed[az ? 0 : 1] = 0.0;
    write(protocol::encodeLine({m}, d));
    (az ? m_targetAz : m_targetEl) = target;
    emit targetChanged(m_targetAz, m_targetEl);
    return true;
}

bool RotatorSession::moveAxis(Axis axis, double degreesPerSecond)
{
    if (!requireLink())
        return false;
    if (!std::isfinite(degreesPerSecond))
        return refuse(tr("speed is not a number"));
    if (degreesPerSecond == 0.0)
        return stop(axis == Axis::Azimuth ? Axes::Azimuth : Axes::Elevation);
    const bool az = axis == Axis::Azimuth;
    const bool positive = degreesPerSecond > 0;
    const auto &lim = m_profile.limits;
    if (hasPosition()) {
        const double at = az ? m_az : m_el;
        const double limit = positive ? (az ? lim.azMax : lim.elMax) : (az ? lim.azMin : lim.elMin);
        if (positive ? at >= limit : at <= limit)
            return refuse(tr("%1 is already at its %2 limit (%3°)")
                              .arg(az ? tr("azimuth") : tr("elevation"), positive ? tr("upper") : tr("lower"))
                              .arg(limit, 0, 'f', 1));
    }
    const Dialect d = m_profile.dialect;
    const Op velocityOp = az ? (positive ? Op::VelocityRight : Op::VelocityLeft)
                             : (positive ? Op::VelocityUp : Op::VelocityDown);
    const Op moveOp = az ? (positive ? Op::MoveRight : Op::MoveLeft) : (positive ? Op::MoveUp : Op::MoveDown);
    QByteArray line;
    if (protocol::dialectSupports(d, velocityOp)) {
        const Message m = Message::number(velocityOp, std::round(std::abs(degreesPerSecond) * 1000.0));
        rememberSent(m);
        line = protocol::encodeLine({m}, d);
    } else if (protocol::dialectSupports(d, moveOp)) {
        line = protocol::encodeLine({Message::query(moveOp)}, d);
    } else {
        return refuse(tr("%1 has no command to move an axis").arg(protocol::dialectName(d)));
    }
    m_jogSpeed[az ? 0 : 1] = degreesPerSecond;
    write(line);
    return true;
}

bool RotatorSession::stop(Axes axes)
{
    // Stop goes straight to the wire, ahead of any waiting query, in every
    // state where there is a link to send it on.
    if (!m_link || !m_link->isOpen())
        return refuse(tr("not connected to a rotator: nothing to stop"));
    const bool az = int(axes) & int(Axes::Azimuth);
    const bool el = int(axes) & int(Axes::Elevation);
    if (az)
        m_jogSpeed[0] = 0.0;
    if (el)
        m_jogSpeed[1] = 0.0;
    const QByteArray line = protocol::encodeStop(az, el, m_profile.dialect);
    if (line.isEmpty())
        return refuse(tr("%1 has no stop command").arg(protocol::dialectName(m_profile.dialect)));
    write(line);
    return true;
}

bool RotatorSession::park()
{
    if (!requireLink())
        return false;
    if (!protocol::dialectSupports(m_profile.dialect, Op::Park))
        return gotoPosition(m_profile.parkAz, m_profile.parkEl);
    m_jogSpeed = {0.0, 0.0};
    write(protocol::encodeLine({Message::query(Op::Park)}, m_profile.dialect));
    m_targetAz = m_profile.parkAz;
    m_targetEl = m_profile.parkEl;
    emit targetChanged(m_targetAz, m_targetEl);
    return true;
}

bool RotatorSession::home()
{
    if (!requireLink())
        return false;
    if (!protocol::dialectSupports(m_profile.dialect, Op::Reset))
        return refuse(tr("%1 has no RESET (homing) command").arg(protocol::dialectName(m_profile.dialect)));
    m_jogSpeed = {0.0, 0.0};
    write(protocol::encodeLine({Message::query(Op::Reset)}, m_profile.dialect));
    return true;
}

bool RotatorSession::readConfig(int reg)
{
    if (!requireLink())
        return false;
    if (!protocol::dialectSupports(m_profile.dialect, Op::ConfigRead))
        return refuse(tr("%1 has no config registers").arg(protocol::dialectName(m_profile.dialect)));
    if (reg < 0 || reg > 99999)
        return refuse(tr("register %1 does not exist").arg(reg));
    Request r;
    r.line = protocol::encodeLine({Message::query(Op::ConfigRead, reg)}, m_profile.dialect);
    r.expects[0] = Expectation{Op::ConfigRead, reg};
    r.expectCount = 1;
    r.attemptsLeft = m_options.retries + 1;
    r.purpose = RequestPurpose::User;
    r.done = [this, line = printable(r.line)](bool ok, const QString &reason) {
        if (!ok)
            emit requestFailed(line, reason);
    };
    if (!m_queue.isFull())
        return enqueue(std::move(r));
    return refuse(tr("the controller is not keeping up: %1 requests already waiting").arg(m_queue.size()));
}

bool RotatorSession::writeConfig(int reg, const QString &value)
{
    if (!requireLink())
        return false;
    if (!protocol::dialectSupports(m_profile.dialect, Op::ConfigWrite))
        return refuse(tr("%1 has no config registers").arg(protocol::dialectName(m_profile.dialect)));
    if (reg < 0 || reg > 99999)
        return refuse(tr("register %1 does not exist").arg(reg));
    const QByteArray text = value.trimmed().toLatin1();
    if (text.isEmpty() || text.size() > 28)
        return refuse(tr("a register value is 1 to 28 characters"));
    for (char c : text) {
        if (c <= ' ' || c > '~' || c == ',' || c == ';')
            return refuse(tr("register value '%1' has a character the protocol cannot carry").arg(value));
    }
    if (reg == 7 || reg == 8) {
        // Park position: a value outside the limits would park into an end stop.
        bool ok = false;
        const double angle = value.toDouble(&ok);
        const QString e = !ok ? tr("park position must be a number")
                          : reg == 7 ? model::chooseAzimuth(m_profile.limits, angle, std::nullopt).error
                                     : model::checkElevation(m_profile.limits, angle);
        if (!e.isEmpty())
            return refuse(e);
    }
    write(protocol::encodeLine({Message::word(Op::ConfigWrite, text, reg)}, m_profile.dialect));
    return true;
}

bool RotatorSession::sendRaw(const QString &line)
{
    if (!requireLink())
        return false;
    const QByteArray bytes = line.trimmed().toLatin1();
    if (bytes.isEmpty())
        return refuse(tr("nothing to send"));
    if (bytes.size() > kMaxRawLine)
        return refuse(tr("a raw line is at most %1 characters").arg(kMaxRawLine));
    for (char c : bytes) {
        if (c < ' ' || c > '~')
            return refuse(tr("a raw line may hold printable ASCII only"));
    }
    // Raw lines pass the same limit checks as every other move.
    QString error;
    protocol::Parser check(m_profile.dialect);
    check.feed(bytes + '\n', [&](const Message &m) {
        if (!error.isEmpty() || !m.hasValue)
            return;
        if (m.op == Op::Azimuth) {
            const auto choice = model::chooseAzimuth(m_profile.limits, m.value, std::nullopt);
            if (!choice.azimuth || std::abs(*choice.azimuth - m.value) > 1e-6)
                error = choice.error.isEmpty() ? tr("azimuth %1° is outside the limits").arg(m.value) : choice.error;
        } else if (m.op == Op::Elevation) {
            error = model::checkElevation(m_profile.limits, m.value);
        }
    });
    if (!error.isEmpty())
        return refuse(error);
    write(bytes + '\n');
    return true;
}

} // namespace slew::session
