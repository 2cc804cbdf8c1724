#pragma once
// Park and Home. Homing (RESET) runs against the end stops and can take a
// while, so it shows progress until GS reports both axes idle again, and can
// be cancelled (which stops the rotator). Nothing here blocks or pops up.

#include "session/rotatorsession.h"

#include <QTimer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace slew::ui {

class ParkHomePanel : public QWidget {
    Q_OBJECT
public:
    static constexpr int kHomingTimeoutMs = 180000;

    explicit ParkHomePanel(session::RotatorSession *session, QWidget *parent = nullptr);

    bool isHoming() const { return m_homing; }

public slots:
    bool park();
    bool home();
    void cancelHoming();  // stops the rotator
    void abandonHoming(); // Stop was pressed elsewhere: just stop waiting

signals:
    void homingFinished(bool ok, const QString &message);

private:
    void onStatus(session::StatusWord status);
    void finish(bool ok, const QString &message);
    void updateEnabled();

    session::RotatorSession *m_session;
    QPushButton *m_park;
    QPushButton *m_home;
    QPushButton *m_cancel;
    QProgressBar *m_progress;
    QLabel *m_message;
    QTimer m_timeout;
    bool m_homing = false;
    bool m_sawMoving = false;
};

} // namespace slew::ui
