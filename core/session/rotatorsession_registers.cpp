// SPDX-License-Identifier: GPL-3.0-or-later
// RotatorSession's registers: reading and writing the controller's config
// registers (CR/CW), and where PARK goes. An Easycomm III or SatNOGS
// controller parks at its own registers CW7/CW8, which need not be what the
// profile says (a fresh profile says 0/90, a fresh controller may hold 0/0).
// So the session reads them once on every connect, as the last part of the
// probe, and until they are in it says the park is not known rather than
// show the profile's guess as if it were the controller's.

#include "rotatorsession.h"

#include "input/finitenumber.h"

#include <cmath>

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {

QString printable(const QByteArray &line)
{
    return QString::fromLatin1(line).trimmed();
}

} // namespace

CommandResult RotatorSession::readConfig(int reg)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (!m_codec->supports(Op::ConfigRead))
        return refuse(tr("%1 has no config registers").arg(m_codec->name()));
    if (reg < 0 || reg > 99999)
        return refuse(tr("register %1 does not exist").arg(reg));
    Request r;
    r.line = m_codec->line({Message::query(Op::ConfigRead, reg)});
    r.expects[0] = Expectation{Op::ConfigRead, reg};
    r.expectCount = 1;
    r.attemptsLeft = m_options.retries + 1;
    r.purpose = RequestPurpose::User;
    r.done = [this, line = printable(r.line)](bool ok, const QString &reason) {
        if (!ok)
            emit requestFailed(line, reason);
    };
    if (m_queue.isFull())
        return refuse(tr("the controller is not keeping up: %1 requests already waiting").arg(m_queue.size()));
    wakePolling();
    enqueue(std::move(r));
    return {};
}

CommandResult RotatorSession::writeConfig(int reg, const QString &value)
{
    if (auto linked = requireLink(); !linked)
        return linked;
    if (!m_codec->supports(Op::ConfigWrite))
        return refuse(tr("%1 has no config registers").arg(m_codec->name()));
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
        const std::optional<double> angle = input::finiteNumber(value);
        if (!angle)
            return refuse(tr("park position must be a finite number"));
        const model::MoveCheck check = previewParkRegister(reg, *angle);
        if (!check.allowed())
            return refuseMove(check.refusal);
    }
    write(m_codec->line({Message::word(Op::ConfigWrite, text, reg)}));
    wakePolling();
    return {};
}

bool RotatorSession::hasParkRegisters() const
{
    // The dialects with CR have CW7/CW8 (docs/protocol.md); GS-232, SPID,
    // Micro-2g and rotctld have no registers and park at the profile's.
    return m_codec->supports(Op::ConfigRead);
}

bool RotatorSession::parkKnown() const
{
    return !hasParkRegisters() || (m_parkRegister[0] && m_parkRegister[1]);
}

double RotatorSession::controllerParkAzimuth() const
{
    return hasParkRegisters() ? m_parkRegister[0].value_or(m_profile.parkAz) : m_profile.parkAz;
}

double RotatorSession::controllerParkElevation() const
{
    return hasParkRegisters() ? m_parkRegister[1].value_or(m_profile.parkEl) : m_profile.parkEl;
}

void RotatorSession::readParkRegistersInProbe()
{
    for (int reg : {7, 8}) {
        Request r;
        r.line = m_codec->line({Message::query(Op::ConfigRead, reg)});
        if (r.line.isEmpty() || m_queue.contains(r.line))
            continue;
        r.expects[0] = Expectation{Op::ConfigRead, reg};
        r.expectCount = 1;
        r.attemptsLeft = m_options.retries + 1;
        r.purpose = RequestPurpose::Probe;
        // The value itself arrives through applyConfig(), as any CR reply does.
        r.done = [this, reg](bool ok, const QString &reason) {
            if (!ok && m_link) // a closing link fails it too, and says why itself
                emit errorOccurred(tr("could not read park register %1: %2; the park position is not known")
                                       .arg(reg)
                                       .arg(reason));
            probeAnswered();
        };
        ++m_probesOutstanding; // before: a full queue answers at once
        enqueue(std::move(r));
    }
}

void RotatorSession::forgetParkRegisters()
{
    // Another link may be another controller: what this one held says
    // nothing about it.
    if (!m_parkRegister[0] && !m_parkRegister[1])
        return;
    m_parkRegister = {};
    emit parkChanged();
}

void RotatorSession::noteParkRegister(int reg, double value)
{
    if (!hasParkRegisters() || (reg != 7 && reg != 8) || !std::isfinite(value))
        return;
    std::optional<double> &held = m_parkRegister[reg - 7];
    if (held == value)
        return;
    held = value;
    emit parkChanged();
}

} // namespace slew::session
