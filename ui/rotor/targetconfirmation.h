#pragma once
// The strip under the polar plot that asks "go to az/el?" after a click on
// the plot, inline rather than in a modal dialog, so the window (and Stop)
// stays live. Confirmation can be turned off for fast pointing.

#include <QPointF>
#include <QWidget>

#include <optional>

class QCheckBox;
class QLabel;
class QPushButton;

namespace slew::ui {

class TargetConfirmation : public QWidget {
    Q_OBJECT
public:
    explicit TargetConfirmation(QWidget *parent = nullptr);

    bool confirmationWanted() const;
    void setConfirmationWanted(bool on);
    std::optional<QPointF> pending() const { return m_pending; }

public slots:
    // `what` names the target when it is more than a point ("preset 'Moon'").
    void ask(double az, double el, const QString &what = {});
    void showProblem(const QString &text); // the picked point cannot be reached
    void accept();
    void cancel();
    void showGoing(double az, double el); // the accepted target went to the wire
    void moveEnded();                     // it has ended: the line goes back to idle

signals:
    void accepted(double az, double el);
    void pendingChanged(std::optional<QPointF> azEl);

private:
    void setPending(std::optional<QPointF> azEl);

    QLabel *m_question;
    QPushButton *m_go;
    QPushButton *m_cancel;
    QCheckBox *m_ask;
    std::optional<QPointF> m_pending;
    bool m_going = false; // the line says where an accepted target is going
};

} // namespace slew::ui
