// SPDX-License-Identifier: GPL-3.0-or-later
#include "controllerradiocommands.h"

#include "controllerchannel.h"

#include "protocol/operations.h"

#include <cmath>

namespace slew::session {

using protocol::Message;
using protocol::Op;

namespace {

Op frequencyOp(ControllerRadioCommands::Path path)
{
    return path == ControllerRadioCommands::Path::Uplink ? Op::UplinkFreq : Op::DownlinkFreq;
}

Op modeOp(ControllerRadioCommands::Path path)
{
    return path == ControllerRadioCommands::Path::Uplink ? Op::UplinkMode : Op::DownlinkMode;
}

} // namespace

ControllerRadioCommands::ControllerRadioCommands(ControllerChannel *channel) : m_channel(channel) {}

bool ControllerRadioCommands::isSupported() const
{
    return m_channel->codec().supports(Op::UplinkFreq);
}

bool ControllerRadioCommands::canRead() const
{
    // Easycomm I is one line out and nothing back.
    return isSupported() && m_channel->codec().answers();
}

CommandResult ControllerRadioCommands::refuseUnlessSupported()
{
    if (auto linked = m_channel->requireLink(); !linked)
        return linked;
    if (!isSupported())
        return m_channel->refuse(
            tr("%1 has no station radio commands (UP, DN)").arg(m_channel->codec().name()));
    return {};
}

CommandResult ControllerRadioCommands::setFrequency(Path path, double hz)
{
    if (auto usable = refuseUnlessSupported(); !usable)
        return usable;
    if (!std::isfinite(hz) || hz < 1.0 || hz > kHighestHz)
        return m_channel->refuse(tr("a radio frequency is 1 Hz to 9999999999 Hz (ten digits), not %1").arg(hz, 0, 'f', 0));
    m_channel->writeCommand(m_channel->codec().line({Message::number(frequencyOp(path), std::round(hz))}));
    return {};
}

CommandResult ControllerRadioCommands::setMode(Path path, const QString &mode)
{
    if (auto usable = refuseUnlessSupported(); !usable)
        return usable;
    const QByteArray text = mode.trimmed().toUpper().toLatin1();
    bool plain = !text.isEmpty() && text.size() <= kLongestMode;
    for (char c : text)
        plain = plain && ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'));
    if (!plain)
        return m_channel->refuse(tr("a radio mode is 1 to 8 letters or digits (USB, FM), not '%1'").arg(mode.left(20)));
    m_channel->writeCommand(m_channel->codec().line({Message::word(modeOp(path), text)}));
    return {};
}

CommandResult ControllerRadioCommands::readFrequency(Path path)
{
    if (auto usable = refuseUnlessSupported(); !usable)
        return usable;
    if (!canRead())
        return m_channel->refuse(tr("%1 answers no station radio queries").arg(m_channel->codec().name()));
    Request r;
    r.line = m_channel->codec().line({Message::query(frequencyOp(path))});
    r.expects[0] = Expectation{frequencyOp(path), -1};
    r.expectCount = 1;
    r.attemptsLeft = 1; // a newer reading is asked for soon enough
    r.purpose = RequestPurpose::User;
    return m_channel->queueRequest(std::move(r), ControllerChannel::SameLine::Shared);
}

void ControllerRadioCommands::read(const Message &m)
{
    const Path path = (m.op == Op::UplinkFreq || m.op == Op::UplinkMode) ? Path::Uplink : Path::Downlink;
    if (m.op == Op::UplinkFreq || m.op == Op::DownlinkFreq) {
        // The parser takes numbers as finite only; out of range is not a reading.
        if (m.hasValue && m.value >= 0 && m.value <= kHighestHz)
            emit frequencyReported(path, m.value);
        return;
    }
    const QString mode = QString::fromLatin1(m.text.view().toByteArray());
    if (!mode.isEmpty())
        emit modeReported(path, mode);
}

} // namespace slew::session
