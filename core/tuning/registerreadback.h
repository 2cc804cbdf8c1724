#pragma once
// Writes config registers with CW and reads every one back with CR, so the
// operator sees per register what the controller really holds. With nothing
// to write it just reads. Used to read the old gains before tuning, to apply
// and to restore gains, and by the wizard's summary.

#include <QList>
#include <QMap>
#include <QObject>
#include <QString>
#include <QTimer>

#include <optional>

namespace slew::session {
class RotatorSession;
}

namespace slew::tuning {

struct RegisterCheck {
    int reg = 0;
    QString written;   // empty when only read
    QString readBack;  // empty when the controller did not answer
    bool answered = false;
    bool ok = false;   // answered, and matches what was written
    QString describe() const; // "CW1 12.5 → CR1 12.50 ok"
};

class RegisterReadback : public QObject {
    Q_OBJECT
public:
    explicit RegisterReadback(session::RotatorSession *session, QObject *parent = nullptr);

    // Starts; false (and nothing sent) when a value is refused or there is no
    // link, with the reason in error(). finished() follows a true return.
    bool run(const QMap<int, QString> &writes, const QList<int> &reads = {});
    bool isRunning() const { return m_running; }
    QString error() const { return m_error; }
    const QList<RegisterCheck> &results() const { return m_results; }
    bool allOk() const;
    std::optional<double> number(int reg) const;

    // Text a register value is written as: enough digits, no exponent.
    static QString format(double value);
    // Whether a read-back value is what was written, at the two decimals the
    // controllers print.
    static bool matches(const QString &written, const QString &readBack);

    void setTimeoutMs(int ms) { m_timer.setInterval(ms); }

signals:
    void finished(bool allOk);

private:
    void onValue(int reg, const QString &value);
    void finish();

    session::RotatorSession *m_session;
    QList<RegisterCheck> m_results;
    QTimer m_timer;
    bool m_running = false;
    QString m_error;
};

} // namespace slew::tuning
