// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The picture of one recorded pass (passreportpicture.h) in a window of
// its own, scaled to fit it, with Save PNG…: shown without modality, never
// exec()'d, so the operator window and its Stop keep working beside it.

#include <QDialog>
#include <QImage>

class QLabel;

namespace slew::ui {

class PassPictureDialog : public QDialog {
    Q_OBJECT
public:
    PassPictureDialog(const QImage &picture, const QString &name, QWidget *parent = nullptr);

    const QImage &picture() const { return m_picture; }

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void showScaled();

    QImage m_picture;
    QString m_name;
    QLabel *m_view;
    QLabel *m_message;
};

} // namespace slew::ui
