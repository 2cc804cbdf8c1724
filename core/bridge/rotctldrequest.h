#pragma once
// One line of Hamlib's rotctld network protocol, read and answered.
//
// The forms Gpredict, the SatNOGS client and Hamlib's own netrotctl send
// (docs/protocol.md lists what they send): short commands (`p`, `P 10 20`, `S`, `K`,
// `R 1`, `M 16 50`, `_`, `q`), long ones (`\get_pos`, `\set_pos 10 20`,
// `\dump_state`), and the extended form: a leading `+` answers with a header
// and key: value lines, any other leading punctuation (`;`, `|`, `,`) also
// replaces the line breaks of the answer with itself. Pure code: no I/O.

#include "protocol/hamliberrors.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

namespace slew::bridge {

// Hamlib's error codes live with the protocol (protocol/hamliberrors.h):
// the rotctld:// peer's refusals are read with the same table.
using protocol::HamlibError;

// "invalid argument", "command rejected", ... (translatable)
QString describeHamlibError(int code);

struct RotctldRequest {
    enum class Kind { SetPosition, GetPosition, Stop, Park, Reset, Move, GetInfo, DumpState, Quit, Unknown, Malformed };

    Kind kind = Kind::Unknown;
    QByteArray name;       // the long name: "set_pos", "get_pos", ... ("" when unknown)
    double az = 0.0, el = 0.0; // set_pos
    int direction = 0;     // move: 2 up, 4 down, 8 left (CCW), 16 right (CW)
    int speed = 0;         // move: 1..100, or -1 for "no change"
    int resetType = 0;     // reset
    bool extended = false; // answer in the extended form
    char separator = '\n'; // between the lines of an extended answer
    QByteArray arguments;  // as written, for the extended echo ("10 20")
    QString error;         // Malformed / Unknown: what was wrong
};

// Parses one line without its terminator. Comma decimals are accepted
// (`P 10,5 20,5`), as Hamlib accepts them.
RotctldRequest parseRotctldLine(QByteArrayView line);

// The answer to a command that returns only a status.
QByteArray formatStatus(const RotctldRequest &request, int code);
// The answer to get_pos: `10.00\n20.00\n`, or the extended form.
QByteArray formatPosition(const RotctldRequest &request, double az, double el);
// The answer to get_info.
QByteArray formatInfo(const RotctldRequest &request, const QString &info);

struct DumpStateLimits {
    double minAz, maxAz, minEl, maxEl;
    int model; // the Hamlib model number that best describes the rotator
};
// `\dump_state`, protocol version 1, as netrotctl reads it on open.
QByteArray formatDumpState(const DumpStateLimits &limits);

} // namespace slew::bridge
