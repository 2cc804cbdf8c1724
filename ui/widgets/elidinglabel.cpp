// SPDX-License-Identifier: GPL-3.0-or-later
#include "widgets/elidinglabel.h"

#include <QFontMetrics>

namespace slew::ui {

ElidingLabel::ElidingLabel(QWidget *parent) : QLabel(parent)
{
    setProperty("elidesText", true); // the layout checks know it shortens on purpose
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Preferred);
}

void ElidingLabel::setFullText(const QString &text)
{
    m_full = text;
    setToolTip(text);
    fit();
    updateGeometry();
}

QSize ElidingLabel::sizeHint() const
{
    const QMargins m = contentsMargins();
    const int margins = m.left() + m.right() + 2 * margin();
    // A little over the advance: elidedText() measures with some slack of
    // its own and would otherwise shorten a text that fits.
    const QFontMetrics fm = fontMetrics();
    const int width = fm.horizontalAdvance(m_full) + 2 * fm.horizontalAdvance(QLatin1Char(' ')) + margins;
    return QSize(m_full.isEmpty() ? 0 : width, QLabel::sizeHint().height());
}

QSize ElidingLabel::minimumSizeHint() const
{
    // Room for a word and the ellipsis; the rest is given when there is room.
    const QFontMetrics fm = fontMetrics();
    return QSize(m_full.isEmpty() ? 0 : fm.horizontalAdvance(QStringLiteral("Azimuth…")), QLabel::minimumSizeHint().height());
}

void ElidingLabel::resizeEvent(QResizeEvent *event)
{
    QLabel::resizeEvent(event);
    fit();
}

void ElidingLabel::fit()
{
    const QString shown = fontMetrics().elidedText(m_full, Qt::ElideRight, std::max(0, contentsRect().width()));
    if (shown != text())
        QLabel::setText(shown);
}

} // namespace slew::ui
