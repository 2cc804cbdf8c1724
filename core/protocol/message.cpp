#include "message.h"

#include <algorithm>
#include <cstring>

namespace slew::protocol {

bool InlineText::assign(QByteArrayView text)
{
    m_size = int(std::min<qsizetype>(text.size(), Capacity));
    if (m_size > 0)
        std::memcpy(m_data.data(), text.data(), size_t(m_size));
    return m_size == text.size();
}

Message Message::query(Op op, int index)
{
    Message m;
    m.op = op;
    m.index = index;
    return m;
}

Message Message::number(Op op, double value, int index)
{
    Message m;
    m.op = op;
    m.index = index;
    m.hasValue = true;
    m.value = value;
    return m;
}

Message Message::word(Op op, QByteArrayView text, int index)
{
    Message m;
    m.op = op;
    m.index = index;
    m.text.assign(text);
    return m;
}

Message Message::invalid(QByteArrayView raw, const char *reason, Refusal kind)
{
    Message m;
    m.op = Op::Invalid;
    m.text.assign(raw);
    m.reason = reason;
    m.refusal = kind;
    return m;
}

bool operator==(const Message &a, const Message &b)
{
    if (a.op != b.op || a.index != b.index || a.hasValue != b.hasValue || !(a.text == b.text))
        return false;
    if (a.hasValue && a.value != b.value)
        return false;
    if (a.op == Op::Encoders && a.encoders != b.encoders)
        return false;
    return true;
}

namespace {
struct OpInfo {
    Op op;
    const char *mnemonic;
    const char *description;
};

// Order matches enum Op so that lookups are an index.
constexpr OpInfo kOps[] = {
    {Op::Invalid, "", "unreadable input"},
    {Op::Azimuth, "AZ", "azimuth"},
    {Op::Elevation, "EL", "elevation"},
    {Op::UplinkFreq, "UP", "uplink frequency"},
    {Op::DownlinkFreq, "DN", "downlink frequency"},
    {Op::UplinkMode, "UM", "uplink mode"},
    {Op::DownlinkMode, "DM", "downlink mode"},
    {Op::UplinkRadio, "UR", "uplink radio"},
    {Op::DownlinkRadio, "DR", "downlink radio"},
    {Op::MoveLeft, "ML", "move left"},
    {Op::MoveRight, "MR", "move right"},
    {Op::MoveUp, "MU", "move up"},
    {Op::MoveDown, "MD", "move down"},
    {Op::StopAzimuth, "SA", "stop azimuth"},
    {Op::StopElevation, "SE", "stop elevation"},
    {Op::Aos, "AO", "acquisition of signal"},
    {Op::Los, "LO", "loss of signal"},
    {Op::SetOutput, "OP", "set output"},
    {Op::ReadInput, "IP", "input"},
    {Op::ReadAnalog, "AN", "analogue input"},
    {Op::Time, "ST", "time"},
    {Op::Version, "VE", "version"},
    {Op::VelocityLeft, "VL", "velocity left"},
    {Op::VelocityRight, "VR", "velocity right"},
    {Op::VelocityUp, "VU", "velocity up"},
    {Op::VelocityDown, "VD", "velocity down"},
    {Op::ConfigRead, "CR", "config read"},
    {Op::ConfigWrite, "CW", "config write"},
    {Op::Status, "GS", "status register"},
    {Op::ErrorFlags, "GE", "error register"},
    {Op::Reset, "RESET", "reset and home"},
    {Op::Park, "PARK", "park"},
    {Op::Encoders, "\\?ENC", "raw encoders"},
    {Op::Alarm, "AL", "alarm"},
    {Op::ConfigValue, "", "config value"},
    {Op::Speed, "X", "speed"},
    {Op::KeepAlive, "?", "keep-alive"},
};
static_assert(std::size(kOps) == size_t(Op::KeepAlive) + 1, "kOps must list every Op");

const OpInfo &info(Op op)
{
    return kOps[size_t(op)];
}
} // namespace

QByteArrayView mnemonic(Op op)
{
    return QByteArrayView(info(op).mnemonic);
}

const char *describe(Op op)
{
    return info(op).description;
}

} // namespace slew::protocol
