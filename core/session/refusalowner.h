// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which command a controller's "no" (`?` from K3NG's Easycom, the `?>`
// prompt of GS-232) answers. A request (a poll, a probe, a register read)
// goes on the wire alone and waits for its answer; a command (a move, a
// park, a stop) goes out beside them and is answered by nothing at all when
// it is taken. A controller answers in the order the lines came, so:
//  - a command whose refusal could still come (within the reply timeout)
//    and that went out before the request on the wire, or with no request
//    on the wire, is what the refusal answers;
//  - once a request written after the command has been answered, the
//    controller has read the command and said nothing: it was taken;
//  - otherwise the request on the wire is refused.
// The one case this cannot tell apart: a command taken in silence and a
// request after it refused before the command was confirmed. The probe
// finds at connect which queries a controller lacks, and they are not
// asked again, so after it a refusal is a command's.

#include <QByteArray>

#include <cstdint>

namespace slew::session {

class RefusalOwner {
public:
    enum class Owner { Request, Command, Nobody };
    struct Answer {
        Owner owner = Owner::Nobody;
        QByteArray line; // the command's line, for Owner::Command
    };

    explicit RefusalOwner(int windowMs = 500) : m_windowMs(windowMs) {}
    void setWindowMs(int ms) { m_windowMs = ms; }

    void noteCommand(const QByteArray &line, qint64 nowMs);
    void noteRequestWritten();
    void noteRequestAnswered(); // the request written last got its answer
    void reset();

    // A refusal came in now; requestOnWire: a request waits for its answer.
    Answer take(bool requestOnWire, qint64 nowMs);

private:
    bool commandPending(qint64 nowMs) const;

    int m_windowMs;
    std::uint64_t m_sequence = 0;        // every line written, in order
    std::uint64_t m_commandAt = 0;       // the last command's place; 0 for none pending
    std::uint64_t m_requestAt = 0;       // the request written last
    qint64 m_commandMs = 0;
    QByteArray m_command;
};

} // namespace slew::session
