#pragma once
// A byte link to a rotator controller: serial port, TCP socket, the built-in
// simulator or a rotctld adaptor. The session talks to every one of them the
// same way and never asks which it has (the way QGroundControl keeps its mock
// link behind the same interface as a serial link).
//
// Opening is asynchronous: open() returns at once and the link later emits
// opened() or failed(). Once open, device() is readable and writable and a
// loss is reported by lost(). Nothing here blocks.

#include <QObject>
#include <QString>

#include <optional>

class QIODevice;

namespace slew::transport {

// What the far end is, known from the link before a byte is exchanged,
// where the link can say (a simulator's URI names its dialect and travel).
// Only what is known is set.
struct LinkHints {
    QString dialect; // as named in profiles and --dialect; empty: not known
    // The link speaks only that dialect (a rotctld server): it replaces one
    // the operator named. Else the dialect is a hint the operator may overrule.
    bool dialectFixed = false;
    // The controller's firmware where its dialect does not say all
    // (protocol/firmware.h): "k3ng", "satnogs"; empty: not known.
    QString firmware;
    std::optional<double> azMax;
    std::optional<double> elMax;
    std::optional<double> parkAz;
    std::optional<double> parkEl;
    // Every line carries the XOR checksum `*HH` both ways (`checksum=1` on
    // the URI; docs/protocol.md, "Checksum"). Not a guess about the far end
    // but a choice the operator made, so the session always follows it.
    bool checksum = false;
    // Which rotor of a multi-rotor controller the link drives (`rotor=2` on
    // the URI; Micro-2g: 1..4). Empty: the controller's default rotor.
    std::optional<int> rotor;
    // The line's rate in bits a second, where the link knows it (a serial
    // port, a simulator paced with `baud=`): the session polls no faster
    // than the line carries (a Rot2Prog at 600 baud takes 0.42 s a poll).
    std::optional<int> baud;
};

class Link : public QObject {
    Q_OBJECT
public:
    explicit Link(QString uri, QObject *parent = nullptr) : QObject(parent), m_uri(std::move(uri)) {}

    // The URI this link was made from, for messages and settings.
    QString uri() const { return m_uri; }

    // The byte stream; valid for the link's lifetime, open between opened()
    // and lost() / close().
    virtual QIODevice *device() = 0;

    virtual void open() = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;

    virtual LinkHints hints() const { return m_hints; }
    void setHints(const LinkHints &hints) { m_hints = hints; }
    // The far end's own clock in seconds, where it keeps one (a simulator
    // stepping simulated time, so that samples stamped with it repeat
    // exactly); empty for hardware, which goes by the wall clock.
    virtual std::optional<double> clockSeconds() const { return std::nullopt; }
    // Whether that clock moves only when the far end is stepped (a simulator
    // on a manual clock, in tests). The session then paces polling, reply
    // timeouts and the stop hold by it (session/linktimer.h), so a test
    // decides how much time passes and a busy machine changes nothing.
    virtual bool clockIsStepped() const { return false; }
    // Runs that clock this many times faster than real time from now on,
    // going on from where it is (a rehearsal at the station clock's rate).
    // False where the far end keeps no clock of its own to scale: hardware,
    // and a simulator on a stepped clock.
    virtual bool setTimeScale(double scale)
    {
        Q_UNUSED(scale);
        return false;
    }
    // How many times faster than real time that clock runs now: 1 where
    // the far end keeps no clock of its own to scale.
    virtual double timeScale() const { return 1.0; }
    // The session calls this with true just before it writes a query it
    // will wait an answer to, and with false once that query is answered,
    // given up or abandoned. Only a link that shares its wire with other
    // sessions (sharedline.h) needs to know; the rest ignore it.
    virtual void setAwaitingReply(bool awaiting) { Q_UNUSED(awaiting); }

signals:
    void opened();
    void failed(const QString &reason); // open() did not succeed
    void lost(const QString &reason);   // an open link went away
    // Something the link itself has to tell the operator, such as an error
    // code a rotctld returned for a command.
    void notice(const QString &message);
    // Travel limits the far end reports (rotctld's \dump_state); moves
    // outside them are refused as well as those outside the profile's.
    void limitsReported(double azMin, double azMax, double elMin, double elMax);
    // A stepped clock moved on to this many seconds.
    void clockStepped(double seconds);

private:
    QString m_uri;
    LinkHints m_hints;
};

} // namespace slew::transport
