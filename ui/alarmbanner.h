#pragma once
// A strip across the top of the window while any alarm (red) or warning
// (amber) holds; hidden when all is well. It only shows what AlarmMonitor says.

#include <QWidget>

class QLabel;

namespace slew::ui {

class AlarmBanner : public QWidget {
    Q_OBJECT
public:
    explicit AlarmBanner(QWidget *parent = nullptr);

    QString text() const;
    bool isSevere() const { return m_severe; }

public slots:
    void showAlarms(const QStringList &alarms, bool severe);

private:
    QLabel *m_text;
    bool m_severe = false;
};

} // namespace slew::ui
