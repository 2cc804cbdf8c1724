#pragma once
// The controller's registers: az/el P, I, D, park az/el (CR1..CR8 / CW1..CW8),
// the read-only ones (control mode, commanded values) and any other register
// the device answers. It reads the device on open, marks what the operator
// changed, and Apply writes only those, reads each back and marks it
// confirmed or mismatched. Values are checked before anything is sent.
// Profiles (limits, park, gains, link) are imported and exported as JSON.
// A controller without registers (SPID) gets a plain note instead: the
// register controls are greyed out, the profile buttons stay.

#include "session/rotatorsession.h"

#include <QMap>
#include <QSet>
#include <QStringList>
#include <QWidget>

class QGridLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace slew::ui {

class ConfigEditor : public QWidget {
    Q_OBJECT
public:
    enum class FieldState { Unknown, Same, Changed, Invalid, Verifying, Confirmed, Mismatched, Failed };
    Q_ENUM(FieldState)

    explicit ConfigEditor(session::RotatorSession *session, QWidget *parent = nullptr);

    FieldState fieldState(int reg) const;
    QString deviceValue(int reg) const;
    QList<int> registers() const { return m_rows.keys(); }

    bool exportProfile(const QString &path, QString *error) const;
    bool importProfile(const QString &path, QString *error);

public slots:
    void readAll();
    int apply(); // how many registers were written; 0 with a message when none could be
    void readRegister(int reg);

signals:
    void profileChanged(); // an imported profile is now the session's

protected:
    void showEvent(QShowEvent *event) override;

private:
    struct Row {
        QLabel *device = nullptr;
        QLineEdit *edit = nullptr; // null: read only
        QLabel *state = nullptr;
        QString deviceText;
        QString written; // the value Apply sent, until it is read back
        FieldState fieldState = FieldState::Unknown;
    };
    Row &rowFor(int reg);
    void onValue(int reg, const QString &text);
    void onRequestFailed(const QString &request, const QString &reason);
    void onEdited(int reg);
    void setState(int reg, FieldState s, const QString &detail = {});
    QString validate(int reg, const QString &text) const;
    void say(const QString &text, bool error);
    void followCapabilities(); // greys out the registers of a controller without any

    session::RotatorSession *m_session;
    QMap<int, Row> m_rows;
    QGridLayout *m_grid;
    QSpinBox *m_extra;
    QLabel *m_message;
    QLabel *m_noRegisters;
    QList<QWidget *> m_registerControls; // what only a controller with registers can use
    bool m_readOnShow = true;
    // A round of reads (Read all) or of read-backs after Apply: the line
    // says how it went once the last register has answered or failed.
    enum class Round { None, Reading, WritingBack };
    void startRound(Round round, const QSet<int> &registers);
    void sayWhenRoundEnds();
    Round m_round = Round::None;
    QSet<int> m_awaiting;
    QSet<int> m_roundRegisters;
    QStringList m_unanswered;
};

} // namespace slew::ui
