// SPDX-License-Identifier: GPL-3.0-or-later
// The SPID frames (spidparser.h) as messages, for code that reads messages:
//   reply (position)        -> Azimuth and Elevation with values (Rot1Prog: elevation 0,
//                              as a position needs both; Micro-2g does the same)
//   status command          -> Azimuth and Elevation queries
//   set command             -> Azimuth and Elevation with values
//   stop command            -> StopAzimuth and StopElevation (Rot1Prog: StopAzimuth)
//   MD-01 move command      -> MoveLeft / MoveRight / MoveUp / MoveDown per direction bit
//   text line (MD-01 log)   -> Alarm with the text
//   skipped bytes, refusals -> Invalid with the reason
// The resolution of a reply (PH, PV) is not in a message: spid::Parser keeps it.

#include "parser.h"

namespace slew::protocol {

namespace {

constexpr std::pair<int, Op> kMoveBits[] = {
    {spid::MoveBit::Left, Op::MoveLeft},
    {spid::MoveBit::Right, Op::MoveRight},
    {spid::MoveBit::Up, Op::MoveUp},
    {spid::MoveBit::Down, Op::MoveDown},
};

} // namespace

int Parser::pushSpid(char c)
{
    m_spid.feed(QByteArrayView(&c, 1), [this](const spid::Frame &f) { deliverSpid(f); });
    return m_readyCount;
}

int Parser::flushSpid()
{
    m_spid.flush([this](const spid::Frame &f) { deliverSpid(f); });
    return m_readyCount;
}

void Parser::deliverSpid(const spid::Frame &f)
{
    using Kind = spid::Frame::Kind;
    // Each message is built in its slot: deliver() takes what makes it.
    // A command names both axes at once; Rot1Prog's only the azimuth.
    const bool twoAxes = m_dialect != Dialect::Rot1Prog;
    auto axes = [&](auto azimuth, auto elevation) {
        deliver(azimuth, !twoAxes);
        if (twoAxes)
            deliver(elevation, true);
    };
    auto query = [](Op op) { return [op] { return Message::query(op); }; };
    auto number = [](Op op, double value) { return [op, value] { return Message::number(op, value); }; };
    switch (f.kind) {
    case Kind::Reply:
        // A position needs both axes: Rot1Prog's elevation reads 0.
        deliver(number(Op::Azimuth, f.azimuth), false);
        deliver(number(Op::Elevation, f.elevation), true);
        return;
    case Kind::Text: deliver([&] { return Message::word(Op::Alarm, f.text.view()); }, true); return;
    case Kind::Skipped:
    case Kind::Refused: deliver([&] { return Message::invalid({}, f.reason); }, true); return;
    case Kind::Command: break;
    }
    switch (f.command) {
    case spid::Command::Status: axes(query(Op::Azimuth), query(Op::Elevation)); return;
    case spid::Command::Set:
        axes(number(Op::Azimuth, f.azimuth), number(Op::Elevation, f.elevation));
        return;
    case spid::Command::Stop: axes(query(Op::StopAzimuth), query(Op::StopElevation)); return;
    case spid::Command::Move:
        for (const auto &[bit, op] : kMoveBits) {
            if (f.moveDirections & bit)
                deliver(query(op), false);
        }
        if (m_readyCount > 0) // the reader refuses a move without a direction
            slot(m_readyCount - 1).lineEnd = true;
        return;
    }
}

} // namespace slew::protocol
