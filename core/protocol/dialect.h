#pragma once
// The command sets Slew speaks: the flavours of Easycomm, Yaesu GS-232, and
// Hamlib's rotctld network protocol, the Micro-2g rotor controller, and the
// binary SPID family (spidcodec.h). docs/protocol.md has the table of every
// command and its wire form per dialect, and why each choice was made.

#include "message.h"

#include <QList>
#include <QString>

#include <cstddef>
#include <optional>

namespace slew::protocol {

enum class Dialect : std::uint8_t {
    Easycomm1, // one line: AZ EL UP mode DN mode; no feedback (Hamlib model 201)
    Easycomm2, // two-letter commands, one decimal, ML/MR/MU/MD (Hamlib model 202)
    Easycomm3, // the Easycomm III derivative: two decimals, VL..VD, CR/CW, GS per axis, \?ENC
    SatNogs,   // SatNOGS firmware: `CR n` answered `n,value`, VE, IP0..8 (Hamlib model 204)
    Gs232A,    // Yaesu GS-232A: W/M/C2/S/A/E/R/L/U/D/X, position `+0aaa+0eee` (Hamlib model 601)
    Gs232B,    // Yaesu GS-232B: the same commands, position `AZ=aaa  EL=eee` (Hamlib model 603)
    Rotctld,   // Hamlib's rotctld over TCP: P, p, S, K, R, M, _; answers `RPRT n` or bare lines
    Micro2g,   // the Micro-2g program: four azimuth rotors, Cn, Mqqq, Sn, Pnm, Lnm; heading `+0123`
    // SPID: binary frames, not lines (spidcodec.h); set, status and stop only.
    Rot2Prog,  // Alfa Rot2Prog: 13-byte commands, 12-byte replies, no answer to a set (Hamlib model 901)
    Rot1Prog,  // Alfa Rot1Prog: azimuth only, 5-byte replies (Hamlib model 902)
    Md01,      // Alfa MD-01/02 in ROT2 mode: answers a set, has a move command (Hamlib model 903)
};

// How a dialect's bytes are framed: one codec each.
enum class Framing : std::uint8_t {
    Lines,      // text lines (encoder.h, parser.h)
    SpidFrames, // SPID's fixed binary frames (spidcodec.h)
};

// The families whose members share a command set and differ in details.
enum class DialectFamily : std::uint8_t { Easycomm, Gs232, Rotctld, Micro2g, Spid };

// Everything about a dialect that is a fact rather than code: one row each,
// in kDialects below. Adding a dialect is a row, and a codec if its framing
// is new (docs/protocol.md, "Adding a dialect").
struct DialectRow {
    Dialect dialect;
    const char *name;      // "easycomm2": --dialect, the profile, the man page
    DialectFamily family;
    Framing framing;
    // The Hamlib rotator model a rotctld client of Slew is told it talks to
    // (`\dump_state`, `_`): the backend of the same protocol, or the dummy
    // (1) where Hamlib has none, netrotctl (2) for a rotctld behind Slew.
    int hamlibModel;
    char terminator;       // what ends a line Slew sends; '\0' without lines
    int angleDecimals;     // how many decimals an angle is written with
    bool azimuthOnly;      // no elevation to command; its position reads as elevation 0
    int rotorsOnLine;      // rotors one controller drives on its one line
    // A set position always names both axes (Easycomm I's one line, GS-232's
    // W, rotctld's P, a SPID frame; Micro-2g's azimuth with its constant 0).
    bool setsBothAxes;
};

// Indexed by the enum's value, in the order the UI lists them.
inline constexpr DialectRow kDialects[] = {
    // dialect             name         family                   framing              model term  dec  az-only rotors both
    {Dialect::Easycomm1, "easycomm1", DialectFamily::Easycomm, Framing::Lines,      201, '\n', 1, false, 1, true},
    {Dialect::Easycomm2, "easycomm2", DialectFamily::Easycomm, Framing::Lines,      202, '\n', 1, false, 1, false},
    {Dialect::Easycomm3, "easycomm3", DialectFamily::Easycomm, Framing::Lines,      204, '\n', 2, false, 1, false},
    {Dialect::SatNogs,   "satnogs",   DialectFamily::Easycomm, Framing::Lines,      204, '\n', 1, false, 1, false},
    {Dialect::Gs232A,    "gs232a",    DialectFamily::Gs232,    Framing::Lines,      601, '\r', 0, false, 1, true},
    {Dialect::Gs232B,    "gs232b",    DialectFamily::Gs232,    Framing::Lines,      603, '\r', 0, false, 1, true},
    {Dialect::Rotctld,   "rotctld",   DialectFamily::Rotctld,  Framing::Lines,      2,   '\n', 2, false, 1, true},
    {Dialect::Micro2g,   "micro2g",   DialectFamily::Micro2g,  Framing::Lines,      1,   '\r', 0, true,  4, true},
    {Dialect::Rot2Prog,  "rot2prog",  DialectFamily::Spid,     Framing::SpidFrames, 901, '\0', 1, false, 1, true},
    {Dialect::Rot1Prog,  "rot1prog",  DialectFamily::Spid,     Framing::SpidFrames, 902, '\0', 0, true,  1, true},
    {Dialect::Md01,      "md01",      DialectFamily::Spid,     Framing::SpidFrames, 903, '\0', 1, false, 1, true},
};

constexpr const DialectRow &dialectRow(Dialect d)
{
    return kDialects[static_cast<std::size_t>(d)];
}

// Every dialect, in the order the UI lists them.
const QList<Dialect> &allDialects();
// "easycomm1, easycomm2, ..., rotctld", for help texts and messages.
QString dialectNameList();
// Inline: the parser asks for every byte.
constexpr bool isGs232(Dialect d)
{
    return dialectRow(d).family == DialectFamily::Gs232;
}
// The binary SPID family: fixed frames (spidcodec.h), which the line
// encoder and the operations table cannot write. encodeToken and
// encodeLine return nothing for them.
constexpr bool isSpid(Dialect d)
{
    return dialectRow(d).framing == Framing::SpidFrames;
}
constexpr bool isAzimuthOnly(Dialect d)
{
    return dialectRow(d).azimuthOnly;
}
constexpr int rotorsOnLine(Dialect d)
{
    return dialectRow(d).rotorsOnLine;
}
constexpr bool setsBothAxesTogether(Dialect d)
{
    return dialectRow(d).setsBothAxes;
}
constexpr char lineTerminator(Dialect d)
{
    return dialectRow(d).terminator;
}
constexpr int angleDecimals(Dialect d)
{
    return dialectRow(d).angleDecimals;
}

QString dialectName(Dialect d);                              // "easycomm2"
std::optional<Dialect> dialectFromName(QStringView name);   // accepts the names above

// Whether a dialect has a command at all. The session uses this to refuse
// (with a message) what the device cannot do, and the UI to grey it out.
bool dialectSupports(Dialect d, Op op);

} // namespace slew::protocol
