// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A one-line label that fits the room it is given: the text is shortened
// with "…" when it does not fit, and shown whole as its tooltip. For a
// state line that shares the status bar with passing messages, where both
// axes resting on their limit switches can say more than fits at 1280×720.

#include <QLabel>

namespace slew::ui {

class ElidingLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidingLabel(QWidget *parent = nullptr);

    void setFullText(const QString &text);
    QString fullText() const { return m_full; }

    QSize sizeHint() const override; // the whole text, when there is room
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void fit();

    QString m_full;
};

} // namespace slew::ui
