// SPDX-License-Identifier: GPL-3.0-or-later
#include "history/passpicturedialog.h"

#include "widgets/filechooser.h"

#include <QDialogButtonBox>
#include <QGuiApplication>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QSaveFile>
#include <QScreen>
#include <QVBoxLayout>

namespace slew::ui {

PassPictureDialog::PassPictureDialog(const QImage &picture, const QString &name, QWidget *parent)
    : QDialog(parent), m_picture(picture), m_name(name)
{
    setObjectName(QStringLiteral("passPictureDialog"));
    setWindowTitle(tr("Pass %1").arg(name));
    m_view = new QLabel;
    m_view->setObjectName(QStringLiteral("passPicture"));
    m_view->setAlignment(Qt::AlignCenter);
    m_view->setMinimumSize(320, 240);
    m_view->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("passPictureMessage"));
    m_message->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close);
    QPushButton *save = buttons->addButton(tr("Save PNG…"), QDialogButtonBox::ActionRole);
    save->setObjectName(QStringLiteral("passPictureSave"));
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    connect(save, &QPushButton::clicked, this, [this] {
        chooseFile(this, FileChoice::Save, tr("Save the pass's picture"), QStringLiteral("pass-%1.png").arg(m_name),
                   tr("PNG images (*.png)"), [this](const QString &path) {
                       QSaveFile file(path);
                       const bool saved = file.open(QIODevice::WriteOnly) && m_picture.save(&file, "PNG") && file.commit();
                       m_message->setText(saved ? tr("Saved to %1").arg(path)
                                                : tr("cannot write %1: %2").arg(path, file.errorString()));
                   });
    });
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_view, 1);
    auto *foot = new QHBoxLayout;
    foot->addWidget(m_message, 1);
    foot->addWidget(buttons);
    layout->addLayout(foot);
    // As large as the screen allows, never larger than the picture.
    QSize size = m_picture.size() + QSize(24, 60);
    if (const QScreen *screen = parent ? parent->screen() : QGuiApplication::primaryScreen())
        size = size.boundedTo(screen->availableSize() * 0.9);
    resize(size);
}

void PassPictureDialog::resizeEvent(QResizeEvent *event)
{
    QDialog::resizeEvent(event);
    showScaled();
}

void PassPictureDialog::showScaled()
{
    const qreal ratio = devicePixelRatioF();
    QPixmap pixmap = QPixmap::fromImage(
        m_picture.scaled(m_view->size() * ratio, Qt::KeepAspectRatio, Qt::SmoothTransformation));
    pixmap.setDevicePixelRatio(ratio);
    m_view->setPixmap(pixmap);
}

} // namespace slew::ui
