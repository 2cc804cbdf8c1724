#pragma once
// One Easycomm token, in either direction.
//
// Easycomm is symmetric: `AZ123.1` is a set command from the host and a
// position report from the controller, `AZ` alone is a query. So the codec has
// one value type for both; the reader (session or simulator) knows which way
// the bytes travelled. A Message owns no heap memory, so the parser can hand
// out thousands per second without allocating.

#include <QByteArrayView>

#include <array>
#include <cstdint>
#include <cstring>

namespace slew::protocol {

// Every mnemonic of the Easycomm command reference (Easycomm I, II, III) and the Easycomm III derivative (the
// Easycomm III derivative), plus the replies real devices send.
enum class Op : std::uint8_t {
    Invalid,       // unreadable input: text holds the raw bytes, reason says why
    Azimuth,       // AZ[angle]      set, report, or query when no value
    Elevation,     // EL[angle]
    UplinkFreq,    // UP[Hz]
    DownlinkFreq,  // DN[Hz]
    UplinkMode,    // UM[word], or the mode word after UPnnn on an Easycomm I line
    DownlinkMode,  // DM[word], or the mode word after DNnnn
    UplinkRadio,   // UR[n]
    DownlinkRadio, // DR[n]
    MoveLeft,      // ML
    MoveRight,     // MR
    MoveUp,        // MU
    MoveDown,      // MD
    StopAzimuth,   // SA
    StopElevation, // SE
    Aos,           // AO
    Los,           // LO
    SetOutput,     // OPn,0|1
    ReadInput,     // IPn, answered IPn,value
    ReadAnalog,    // ANn, answered ANn,value
    Time,          // ST[YY:MM:DD:HH:mm:SS]
    Version,       // VE[text]
    VelocityLeft,  // VL[mdeg/s]
    VelocityRight, // VR[mdeg/s]
    VelocityUp,    // VU[mdeg/s]
    VelocityDown,  // VD[mdeg/s]
    ConfigRead,    // CRn (or `CR n`), answered CRn,value
    ConfigWrite,   // CWn,value
    Status,        // GS[bits]
    ErrorFlags,    // GE[bits]
    Reset,         // RESET
    Park,          // PARK
    Encoders,      // \?ENC[az,el,vaz,vel] raw encoder ticks
    Alarm,         // AL[text], sent unsolicited by an Easycomm II controller
    ConfigValue,   // n,value   SatNOGS' answer to `CR n` (no CR prefix)
    // GS-232 only (docs/protocol.md); the position and stop commands of
    // GS-232 map onto Azimuth, Elevation, StopAzimuth, StopElevation, Move*.
    Speed,         // Xn, n 1..4: the speed of the manual moves
    KeepAlive,     // ?   (a keep-alive), answered `OK` (docs/protocol.md: Slew's choice)
    Offset,        // O+aaa-eee: a relative move. One message per axis, index 0 azimuth, 1
                   // elevation, value the signed offset in degrees (GS-232's O, the easycom library)
    // Micro-2g only (docs/protocol.md): index is the rotor, -1 for the default one.
    SelectRotor,   // n: make rotor n (value) the default rotor
    Preset,        // Pm / Pnm: turn to preset m (value, 1..3)
    StorePreset,   // Lm / Lnm: store the present heading as preset m
    Tolerance,     // T (query) / Tn x (set rotor n to x A/D counts); answered `T1=20 T2=20 ...` (text)
    Calibration,   // Z (query) / ZnL mmm, ZnR xxxx=yyy, ZnD mmm (text after Zn); answered a line per rotor
    AdcReadings,   // V: answered `V1=3990 V2=...` (text)
    RelayBits,     // R: answered `R1=- R2=L ...` (text)
    // rotctld only (docs/protocol.md): its other answers map onto Azimuth,
    // Elevation, Version and Alarm.
    Report,        // RPRT 0: a command done; value holds the code
    // A controller's "no" to the command before it: `?` (K3NG's Easycom),
    // `?>` (a Yaesu GS-232 prompt, K3NG's GS-232). text holds the answer.
    Refused,
};

// Why a token was refused, for code that counts or answers by kind; the
// reason string is for people.
enum class Refusal : std::uint8_t { None, Unknown, Malformed, Overlong };

// A short string stored inline. Longer input is refused by the parser before
// it gets here, so the cap is also the protocol's longest token.
class InlineText {
public:
    static constexpr int Capacity = 128;

    InlineText() = default;
    explicit InlineText(QByteArrayView text) { assign(text); }
    // Only the bytes in use are copied: a message is copied a few times on
    // its way out of the parser, and most carry no text at all.
    InlineText(const InlineText &other) : m_size(other.m_size) { copyFrom(other); }
    InlineText &operator=(const InlineText &other)
    {
        if (this != &other) {
            m_size = other.m_size;
            copyFrom(other);
        }
        return *this;
    }

    // Keeps at most Capacity bytes; returns false when text was cut.
    bool assign(QByteArrayView text);
    void clear() { m_size = 0; }

    QByteArrayView view() const { return {m_data.data(), m_size}; }
    bool isEmpty() const { return m_size == 0; }
    int size() const { return m_size; }

    friend bool operator==(const InlineText &a, const InlineText &b) { return a.view() == b.view(); }

private:
    void copyFrom(const InlineText &other)
    {
        if (m_size > 0) // most messages carry no text: no call at all
            std::memcpy(m_data.data(), other.m_data.data(), size_t(m_size));
    }

    // Not cleared on construction: only the first m_size bytes are ever read,
    // and clearing 128 bytes for every token was most of the parser's time.
    std::array<char, Capacity> m_data;
    int m_size = 0;
};

struct Message {
    Op op = Op::Invalid;
    int index = -1;         // register, input or output number; -1 when absent
    bool hasValue = false;  // false: a query (AZ, GS, CR1) or a bare command
    double value = 0.0;     // angle, Hz, mdeg/s, bits, or the numeric form of text
    std::array<double, 4> encoders{}; // Op::Encoders: az, el, az velocity, el velocity
    InlineText text;        // word argument (mode, version, register value, alarm)
    const char *reason = nullptr; // Op::Invalid: why the token was refused (static string)
    Refusal refusal = Refusal::None; // Op::Invalid: the kind of refusal
    bool lineEnd = false;   // the token was ended by CR or LF, not by a space (framing only:
                            // a device answers a whole line at once; not compared by ==)

    bool isQuery() const { return !hasValue && text.isEmpty(); }
    bool isValid() const { return op != Op::Invalid; }

    // Convenience constructors for the common forms.
    static Message query(Op op, int index = -1);
    static Message number(Op op, double value, int index = -1);
    static Message word(Op op, QByteArrayView text, int index = -1);
    static Message invalid(QByteArrayView raw, const char *reason, Refusal kind = Refusal::Malformed);
};

bool operator==(const Message &a, const Message &b);

// The mnemonic as it appears on the wire ("AZ", "RESET", "\\?ENC"); empty for
// ConfigValue and Invalid, which have none.
QByteArrayView mnemonic(Op op);

// A readable name for logs and the traffic console ("azimuth", "config read").
const char *describe(Op op);

} // namespace slew::protocol
