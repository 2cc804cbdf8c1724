// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A controller's language, as the session speaks it: what to send to set a
// position, stop, jog or ask where the antenna is, and the messages its
// replies hold. The session asks the codec and never which dialect it
// talks: the facts are the dialect's row (dialect.h), and how the bytes are
// framed is the codec's kind, one per Framing:
//
//   LineCodec       text lines: Easycomm, GS-232, rotctld, Micro-2g (linecodec.h)
//   SpidFrameCodec  SPID's fixed binary frames (spidframecodec.h)
//
// Adding a dialect is a row, and a codec only if its framing is new
// (docs/protocol.md, "Adding a dialect"). Pure code: no I/O, no signals.

#include "dialect.h"
#include "message.h"
#include "parser.h"

#include <QByteArray>
#include <QString>

#include <array>
#include <initializer_list>
#include <memory>
#include <optional>

namespace slew::protocol {

// Bytes to send, or why there are none (bytes empty, refusal said).
struct Encoded {
    QByteArray bytes;
    QString refusal;
    // What a controller that echoes its commands would send back, so an
    // echo is not read as a report (Easycomm's speed `VL1500`).
    std::optional<Message> echo;
    bool ok() const { return refusal.isEmpty(); }
};

class Codec {
public:
    // The codec of the dialect's framing. rotor names one rotor of a
    // multi-rotor controller (Micro-2g: 1..4; 0 the default one).
    static std::unique_ptr<Codec> forDialect(Dialect d, int rotor = 0);
    virtual ~Codec() = default;
    Codec(const Codec &) = delete;
    Codec &operator=(const Codec &) = delete;

    Dialect dialect() const { return m_dialect; }
    bool speaks(Dialect d) const { return d == m_dialect; }
    const DialectRow &row() const { return dialectRow(m_dialect); }
    QString name() const { return dialectName(m_dialect); } // for messages: "gs232b"
    int rotor() const { return m_rotor; }
    void setRotor(int rotor) { m_rotor = rotor; }
    // Whether the controller has a command at all (the operations table).
    bool supports(Op op) const { return dialectSupports(m_dialect, op); }

    // --- Reading: bytes in, messages out -------------------------------
    // Calls sink(const Message &) for every message the bytes complete.
    template <typename Sink>
    void feed(QByteArrayView bytes, Sink &&sink)
    {
        m_parser.feed(bytes, std::forward<Sink>(sink));
    }
    // Forgets a half-read reply (the link reopened).
    void resetReading() { m_parser.reset(); }
    // Bytes wait for the rest of their reply (a rotctld `p` answer's first line).
    bool hasUnfinishedInput() const { return m_parser.hasUnfinishedLine(); }

    // --- What it can do, beyond single commands ------------------------
    bool setsBothAxes() const { return row().setsBothAxes; }
    // It answers at all (Easycomm I is one line out and nothing back).
    bool answers() const { return !queryPosition().isEmpty(); }
    bool isAzimuthOnly() const { return row().azimuthOnly; }
    // A command that runs an axis (a speed, or a bare move). Without one a
    // jog goes as set-position legs (session/joglegs.h).
    virtual bool jogsItself() const = 0;
    // Its stop halts every axis, whichever were asked: an axis still held
    // on the jog pad must be started again.
    virtual bool stopHaltsEveryAxis() const = 0;
    // It reads text lines: an operator's raw line can be sent, and a line
    // among its replies is the controller's (an alarm). Without, a text
    // line is only firmware logging among the frames.
    virtual bool readsTextLines() const = 0;

    // --- Writing --------------------------------------------------------
    // Both axes (degrees as the controller counts them).
    virtual Encoded setPosition(double azimuth, double elevation) const = 0;
    // One axis, where the dialect can set one alone (not setsBothAxes).
    Encoded setAxis(bool azimuth, double degrees) const;
    // The smallest step a set can make, in degrees.
    virtual double setResolutionDeg() const = 0;
    // Runs the axes at these speeds (°/s, signed; 0 stops none): `changed`
    // is the one just pressed. Only where jogsItself().
    virtual Encoded jog(const std::array<double, 2> &degreesPerSecond, bool changedIsAzimuth) const = 0;
    // Empty when the dialect has none.
    QByteArray stop(bool azimuth, bool elevation) const;
    // A zero speed after a stop, which brakes a drive that would coast.
    QByteArray stopHold(bool azimuth, bool elevation) const;
    QByteArray queryPosition() const;
    // The bytes the answer to queryPosition() takes on the wire.
    int positionReplyBytes() const;
    // Any other command (park, reset, registers, keep-alive, the station
    // radio's UP/DN, calibration): empty when the dialect lacks one of them
    // or has no lines to write it in.
    QByteArray line(std::initializer_list<Message> messages) const;

    // --- An operator's raw line -----------------------------------------
    // Why a line that read as `m` cannot be checked before it is sent
    // (rotctld's other commands, a GS-232 `O` that does not read, a
    // Micro-2g go-to that does not); empty when its meaning is known.
    virtual QString rawLineRefusal(const Message &m) const;
    // A set azimuth is a bearing the controller reaches the short way
    // (Micro-2g's Mqqq), not a position on its travel.
    virtual bool azimuthIsBearing() const { return false; }

protected:
    Codec(Dialect d, int rotor) : m_parser(d), m_dialect(d), m_rotor(rotor) {}
    Parser m_parser;

private:
    Dialect m_dialect;
    int m_rotor;
};

} // namespace slew::protocol
