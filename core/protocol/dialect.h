#pragma once
// The command sets Slew speaks: the flavours of Easycomm, Yaesu GS-232, and
// Hamlib's rotctld network protocol, the Micro-2g rotor controller, and the
// binary SPID family (spidcodec.h). docs/protocol.md has the table of every
// command and its wire form per dialect, and why each choice was made.

#include "message.h"

#include <QList>
#include <QString>

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

// Every dialect, in the order the UI lists them.
const QList<Dialect> &allDialects();
// "easycomm1, easycomm2, ..., rotctld", for help texts and messages.
QString dialectNameList();
// Inline: the parser asks for every byte.
constexpr bool isGs232(Dialect d)
{
    return d == Dialect::Gs232A || d == Dialect::Gs232B;
}
// The binary SPID family: fixed frames (spidcodec.h), which the line
// encoder and the operations table cannot write. encodeToken and
// encodeLine return nothing for them.
constexpr bool isSpid(Dialect d)
{
    return d == Dialect::Rot2Prog || d == Dialect::Rot1Prog || d == Dialect::Md01;
}
// A controller of azimuth rotors only (Micro-2g, Rot1Prog): no elevation to command,
// and its position reads as elevation 0.
bool isAzimuthOnly(Dialect d);
// How many rotors one controller of this dialect drives on its one line
// (the Micro-2g: 4); 1 for every other dialect.
int rotorsOnLine(Dialect d);

// Whether a set position always names both axes (Easycomm I's one line,
// GS-232's W, rotctld's P): a one-axis move must then name the other too.
bool setsBothAxesTogether(Dialect d);

// What ends a line Slew sends: `\n` for Easycomm and rotctld, `\r` for GS-232
// and Micro-2g; `\0` for SPID, which has no lines.
char lineTerminator(Dialect d);

QString dialectName(Dialect d);                              // "easycomm2"
std::optional<Dialect> dialectFromName(QStringView name);   // accepts the names above

// Whether a dialect has a command at all. The session uses this to refuse
// (with a message) what the device cannot do, and the UI to grey it out.
bool dialectSupports(Dialect d, Op op);

// How many decimals the dialect writes for an angle.
int angleDecimals(Dialect d);

} // namespace slew::protocol
