// SPDX-License-Identifier: GPL-3.0-or-later
#include "layoutfaults.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QWidget>

namespace {

QString nameOf(const QWidget *w)
{
    QString text;
    if (const auto *label = qobject_cast<const QLabel *>(w))
        text = label->text().left(30);
    else if (const auto *button = qobject_cast<const QAbstractButton *>(w))
        text = button->text().left(30);
    QString name = QStringLiteral("%1 %2").arg(QLatin1String(w->metaObject()->className()), w->objectName());
    if (!text.isEmpty())
        name += QStringLiteral(" '%1'").arg(text);
    if (w->objectName().isEmpty() && w->parentWidget())
        name += QStringLiteral(" in %1").arg(nameOf(w->parentWidget()));
    return name.trimmed();
}

void collectLaidOut(QLayout *layout, QList<QWidget *> *out)
{
    for (int i = 0; i < layout->count(); ++i) {
        QLayoutItem *item = layout->itemAt(i);
        if (QWidget *w = item->widget(); w && w->isVisible())
            *out << w;
        else if (QLayout *inner = item->layout())
            collectLaidOut(inner, out);
    }
}

// A widget that shortens its own text on purpose says so with this property.
bool elidesOnPurpose(const QWidget *w)
{
    return w->property("elidesText").toBool();
}

QString textFault(const QWidget *w)
{
    const QFontMetrics fm = w->fontMetrics();
    if (const auto *label = qobject_cast<const QLabel *>(w)) {
        if (label->text().isEmpty() || !label->pixmap().isNull())
            return {};
        if (label->wordWrap()) {
            // Wrapped text is cut when its lines need more height than it has.
            const int needed = label->heightForWidth(label->width());
            if (label->height() + 1 < needed)
                return QStringLiteral("%1 cut: its lines need %2 px of height, it has %3")
                    .arg(nameOf(w))
                    .arg(needed)
                    .arg(label->height());
            return {};
        }
        if (label->width() + 1 < label->sizeHint().width())
            return QStringLiteral("%1 cut: %2 px wide, its text needs %3")
                .arg(nameOf(w))
                .arg(label->width())
                .arg(label->sizeHint().width());
        return {};
    }
    if (const auto *check = qobject_cast<const QCheckBox *>(w); check || qobject_cast<const QRadioButton *>(w)) {
        if (w->width() + 1 < w->sizeHint().width())
            return QStringLiteral("%1 cut: %2 px wide, needs %3").arg(nameOf(w)).arg(w->width()).arg(w->sizeHint().width());
        return {};
    }
    if (const auto *button = qobject_cast<const QPushButton *>(w)) {
        QString text = button->text();
        text.remove(QLatin1Char('&'));
        const int needed = fm.horizontalAdvance(text) + 8;
        if (!text.isEmpty() && button->width() < needed)
            return QStringLiteral("%1 cut: %2 px wide, its text needs %3").arg(nameOf(w)).arg(button->width()).arg(needed);
        return {};
    }
    if (const auto *field = qobject_cast<const QLineEdit *>(w)) {
        // A spin box's or a combo box's own field is the owner's business.
        if (qobject_cast<const QComboBox *>(w->parentWidget()) || !w->parentWidget()->layout())
            return {};
        const QString shown = field->text().isEmpty() ? field->placeholderText() : QString();
        const int needed = fm.horizontalAdvance(shown) + 10;
        if (!shown.isEmpty() && field->width() < needed)
            return QStringLiteral("%1 cut: '%2' needs %3 px, the field is %4")
                .arg(nameOf(w), shown)
                .arg(needed)
                .arg(field->width());
        return {};
    }
    if (const auto *combo = qobject_cast<const QComboBox *>(w)) {
        const int needed = fm.horizontalAdvance(combo->currentText()) + 28; // the arrow
        if (!combo->currentText().isEmpty() && combo->width() < needed)
            return QStringLiteral("%1 cut: '%2' needs %3 px, the box is %4")
                .arg(nameOf(w), combo->currentText())
                .arg(needed)
                .arg(combo->width());
        return {};
    }
    return {};
}

void walk(QWidget *w, QStringList *faults)
{
    if (QLayout *layout = w->layout()) {
        QList<QWidget *> laidOut;
        collectLaidOut(layout, &laidOut);
        for (qsizetype i = 0; i < laidOut.size(); ++i) {
            QWidget *a = laidOut[i];
            // As layouts decide: a minimum size set on the widget wins over its
            // hint, each way; a maximum below both is as small as it wants.
            const QSize hint = a->minimumSizeHint();
            const QSize least = QSize(a->minimumWidth() > 0 ? a->minimumWidth() : hint.width(),
                                      a->minimumHeight() > 0 ? a->minimumHeight() : hint.height())
                                    .boundedTo(a->maximumSize());
            const QSizePolicy policy = a->sizePolicy();
            const bool widthMatters = policy.horizontalPolicy() != QSizePolicy::Ignored;
            const bool heightMatters = policy.verticalPolicy() != QSizePolicy::Ignored;
            if (least.isValid()
                && ((widthMatters && a->width() + 1 < least.width())
                    || (heightMatters && a->height() + 1 < least.height())))
                *faults << QStringLiteral("%1 squeezed to %2x%3, its least is %4x%5")
                               .arg(nameOf(a))
                               .arg(a->width())
                               .arg(a->height())
                               .arg(least.width())
                               .arg(least.height());
            for (qsizetype j = i + 1; j < laidOut.size(); ++j) {
                const QRect both = a->geometry().intersected(laidOut[j]->geometry());
                if (both.width() > 1 && both.height() > 1)
                    *faults << QStringLiteral("%1 over %2").arg(nameOf(a), nameOf(laidOut[j]));
            }
        }
    }
    if (!elidesOnPurpose(w))
        if (QString fault = textFault(w); !fault.isEmpty())
            *faults << fault;
    for (QWidget *child : w->findChildren<QWidget *>(Qt::FindDirectChildrenOnly))
        if (child->isVisible() && !child->isWindow())
            walk(child, faults);
}

} // namespace

QStringList layoutFaults(QWidget *top)
{
    // The layout as it settles. A label's new text re-lays its parent, whose
    // new size hint re-lays the next one up: one level per posted
    // LayoutRequest, and a round of sendPostedEvents sends only the events
    // posted before it began. Checked mid-chain, a grid could be seen
    // squeezed inside a parent not yet grown for it (once, on a loaded
    // machine, a readout's four rows at 21 px each). A widget tree is far
    // less than 32 levels deep.
    for (int level = 0; level < 32; ++level)
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    QStringList faults;
    walk(top, &faults);
    return faults;
}
