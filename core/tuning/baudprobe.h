#pragma once
// Finds the baud rate a serial controller answers at: opens the port at each
// common rate in turn and asks for the position. A link with no baud rate
// (TCP, rotctld, the simulator) is tried once as it is.

#include "probeattempt.h"
#include "protocol/dialect.h"

#include <QList>
#include <QObject>
#include <QTimer>

#include <memory>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

struct BaudResult {
    qint32 baud = 0;  // 0: the link has no baud rate
    QString uri;      // what was opened
    bool answered = false;
    QString detail;   // "answered AZ12.00 EL0.00", "no answer in 2 s", the link error
};

class BaudProbe : public QObject {
    Q_OBJECT
public:
    explicit BaudProbe(QObject *parent = nullptr);
    ~BaudProbe() override;

    static bool isSerial(const QString &uri);
    // The URI with its baud query item set (added or replaced).
    static QString withBaud(const QString &uri, qint32 baud);

    void setAttemptMs(int ms) { m_attempt.setLimitMs(ms); }
    // Starts; false (with error()) for an empty URI.
    bool start(const QString &uri, protocol::Dialect dialect = protocol::Dialect::Easycomm3);
    void cancel();
    bool isRunning() const { return m_attempt.isRunning(); }
    QString error() const { return m_error; }
    const QList<BaudResult> &results() const { return m_results; }
    // The first URI that answered; empty when none did.
    QString answeringUri() const;

signals:
    void progress(int percent, const QString &what);
    void tried(const slew::tuning::BaudResult &result);
    void finished(bool anyAnswered);

private:
    void next();
    void conclude(bool answered, const QString &detail);

    QList<BaudResult> m_results;
    QList<qint32> m_pending;
    QString m_uri;
    protocol::Dialect m_dialect = protocol::Dialect::Easycomm3;
    ProbeAttempt m_attempt;
    int m_total = 0;
    QString m_error;
};

} // namespace slew::tuning
