#pragma once
// One controller line shared by several sessions.
//
// A multi-rotor controller (the Micro-2g: four rotors on one serial line)
// is one port that opens once, but each rotor wants a session of its own:
// its own polling, gate, stop and rotctld port. A SharedLine owns the one
// real link and hands each session a link of its own for one rotor
// (`rotor=n` on its URI). Those links share the wire by two rules:
//
//  - A query (a line the session will wait an answer to; the session says
//    so with Link::setAwaitingReply) holds the wire until it is answered or
//    given up. Another rotor's query waits its turn, so every answer reaches
//    the session that asked. Controllers like this one do not say which
//    rotor an answer is for.
//  - A command (a move, a stop) goes out at once, whoever holds the wire:
//    the controller answers none of them, and a stop must never wait.
//
// Bytes that arrive while no query holds the wire go to the rotor that
// wrote last (a refusal `?> ...` of its command). The line opens when the
// first rotor's link opens and closes when the last one closes; a lost line
// is reported to every rotor, and each reopens it in its own time.

#include "link.h"
#include "linkfactory.h"

#include <QByteArray>
#include <QList>
#include <QObject>
#include <QPointer>

#include <memory>

namespace slew::transport {

class SharedLineLink;

class SharedLine : public QObject {
    Q_OBJECT
public:
    // `uri` is the line's, with or without a `rotor=`: that is dropped.
    explicit SharedLine(const QString &uri, QObject *parent = nullptr);
    ~SharedLine() override;

    // The line's URI, without a rotor; and whether the link could be made
    // from it (if not, error() says why and every rotor's link fails).
    QString uri() const { return m_uri; }
    bool isValid() const { return m_line != nullptr; }
    QString error() const { return m_error; }

    // A link to one rotor on this line, unopened, for
    // RotatorSession::setLinkMaker. Its URI must name this line (any
    // `rotor=` aside); without a `rotor=` it drives rotor 1, since the
    // controller's default rotor moves with every other rotor's go-to. The
    // caller owns the link.
    LinkResult makeLink(const QString &uri);

    // The real link, for diagnostics and tests (the simulator behind a
    // `sim:` line); null if it could not be made.
    Link *line() const { return m_line.get(); }
    bool isOpen() const { return m_line && m_line->isOpen(); }
    // Queries waiting for the wire now; bytes no rotor could take.
    int queriesWaiting() const { return int(m_waiting.size()); }
    qint64 bytesDropped() const { return m_bytesDropped; }

    // `uri` without its `rotor=` item: the line it is on.
    static QString lineUri(const QString &uri);
    // The line's URI with `rotor=n` (1..4) added: one rotor on it.
    static QString rotorUri(const QString &lineUri, int rotor);

private:
    friend class SharedLineLink;
    void openFor(SharedLineLink *rotor);
    void closeFor(SharedLineLink *rotor);
    void sendQuery(SharedLineLink *rotor, const QByteArray &bytes);
    void sendCommand(SharedLineLink *rotor, const QByteArray &bytes);
    void queryDone(SharedLineLink *rotor);
    void forget(SharedLineLink *rotor);

    void onOpened();
    void onDown(const QString &reason, bool opening);
    void onReadyRead();
    void writeToLine(SharedLineLink *rotor, const QByteArray &bytes);
    void releaseWire();

    QString m_uri;
    QString m_error;
    std::unique_ptr<Link> m_line;
    QList<SharedLineLink *> m_rotors;      // every link made, open or not
    QList<SharedLineLink *> m_opening;     // waiting for the line to open
    QList<SharedLineLink *> m_open;        // the line is open for these
    SharedLineLink *m_holder = nullptr;    // its query is on the wire
    SharedLineLink *m_lastWriter = nullptr;
    struct WaitingQuery {
        SharedLineLink *rotor;
        QByteArray bytes;
    };
    QList<WaitingQuery> m_waiting;
    qint64 m_bytesDropped = 0;
};

} // namespace slew::transport
