#pragma once
// Works out which Easycomm flavour a controller speaks, or whether it is a
// Micro-2g, by talking to it in each one and counting what it answers
// (position, VE, GS, GE, IP, CR, \?ENC; the Micro-2g's heading and `?`)
// against what it leaves unanswered. The dialect that explains the most
// wins; on a tie the one listed first (easycomm3, satnogs, easycomm2, gs232b,
// micro2g). GS-232B (K3NG's controllers by default) and the Micro-2g are
// asked only when no Easycomm flavour got a position, and
// SPID's binary status frame (Rot2Prog, then Rot1Prog) only when nothing
// did, unless the link runs at a SPID rate (600 or 1200 baud), where SPID
// is asked first. An MD-01/02 answers as a Rot2Prog. Easycomm I answers
// nothing, so it can only be chosen by hand.

#include "probeattempt.h"
#include "protocol/dialect.h"
#include "protocol/firmware.h"
#include "session/sessiontypes.h"

#include <QList>
#include <QObject>
#include <QTimer>

#include <memory>
#include <optional>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

struct DialectResult {
    protocol::Dialect dialect = protocol::Dialect::Easycomm3;
    // The firmware, where its answers tell: the SatNOGS dialect's own, or
    // K3NG's, whose Easycom says `?` to what it lacks where others are silent.
    protocol::Firmware firmware = protocol::Firmware::Generic;
    session::Capabilities capabilities;
    QString version;
    int score = 0; // queries answered minus queries left unanswered
    QString describe() const; // "easycomm3: position, VE, GS, GE, IP, CR/CW, \?ENC"
};

class DialectIdentifier : public QObject {
    Q_OBJECT
public:
    explicit DialectIdentifier(QObject *parent = nullptr);
    ~DialectIdentifier() override;

    void setAttemptMs(int ms) { m_attempt.setLimitMs(ms); }
    bool start(const QString &uri);
    void cancel();
    bool isRunning() const { return m_attempt.isRunning(); }
    QString error() const { return m_error; }
    const QList<DialectResult> &results() const { return m_results; }
    std::optional<DialectResult> best() const;

signals:
    void progress(int percent, const QString &what);
    void finished(bool identified);

private:
    void next();
    void conclude(const session::Capabilities &caps);

    QString m_uri;
    QList<protocol::Dialect> m_pending;
    QList<DialectResult> m_results;
    int m_total = 1; // dialects asked in this run
    ProbeAttempt m_attempt;
    QString m_error;
    bool m_joinedGs232Report = false; // this attempt heard `AZ=059EL=025`
};

} // namespace slew::tuning
