#include "windowsnapshot.h"

#include <QCoreApplication>
#include <QPixmap>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <cstdio>

namespace slew::ui {

void scheduleWindowSnapshot(QWidget *window, const QString &path, int settleMs)
{
    QPointer<QWidget> target(window);
    QTimer::singleShot(std::max(0, settleMs), window, [target, path] {
        if (!target)
            return;
        const QPixmap image = target->grab();
        const bool ok = !image.isNull() && image.save(path, "PNG");
        std::fprintf(ok ? stdout : stderr, ok ? "screenshot written to %s (%dx%d)\n" : "cannot write screenshot %s\n",
                     qPrintable(path), image.width(), image.height());
        QCoreApplication::exit(ok ? 0 : 1);
    });
}

} // namespace slew::ui
