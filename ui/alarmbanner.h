#pragma once
// A red strip across the top of the window while any alarm holds; hidden
// when all is well. It only shows what AlarmMonitor says.

#include <QWidget>

class QLabel;

namespace slew::ui {

class AlarmBanner : public QWidget {
    Q_OBJECT
public:
    explicit AlarmBanner(QWidget *parent = nullptr);

    QString text() const;

public slots:
    void showAlarms(const QStringList &alarms);

private:
    QLabel *m_text;
};

} // namespace slew::ui
