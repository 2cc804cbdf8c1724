#include "operatortheme.h"

#include <QApplication>
#include <QIcon>
#include <QPainter>
#include <QPalette>
#include <QProxyStyle>
#include <QStyleFactory>
#include <QStyleOption>

namespace slew::ui {
namespace {

// Fusion draws a check box's or radio button's outline from the window
// colour, darker; on this dark palette that outline is all but the colour
// of the window itself, and an unticked box cannot be seen. This style
// draws Fusion's indicator and then a light outline round it.
class OperatorStyle : public QProxyStyle {
public:
    OperatorStyle() : QProxyStyle(QStyleFactory::create(QStringLiteral("Fusion"))) {}

    void drawPrimitive(PrimitiveElement element, const QStyleOption *option, QPainter *painter,
                       const QWidget *widget) const override
    {
        QProxyStyle::drawPrimitive(element, option, painter, widget);
        const bool box = element == PE_IndicatorCheckBox || element == PE_IndicatorItemViewItemCheck;
        if (!box && element != PE_IndicatorRadioButton)
            return;
        painter->save();
        painter->setRenderHint(QPainter::Antialiasing);
        const bool enabled = option->state & State_Enabled;
        painter->setPen(QPen(enabled ? kIndicatorOutline : kIndicatorOutline.darker(160), 1.2));
        painter->setBrush(Qt::NoBrush);
        const QRectF r = QRectF(option->rect).adjusted(0.5, 0.5, -0.5, -0.5);
        if (box)
            painter->drawRoundedRect(r, 2, 2);
        else
            painter->drawEllipse(r);
        painter->restore();
    }

    static inline const QColor kIndicatorOutline{0x9a, 0xa6, 0xb3};
};

} // namespace

void applyOperatorTheme(QApplication &app)
{
    app.setStyle(new OperatorStyle); // the application takes ownership
    QPalette p;
    const QColor window(0x23, 0x27, 0x2e), base(0x1a, 0x1e, 0x24), text(0xdc, 0xe2, 0xea);
    const QColor disabled(0x6a, 0x72, 0x7c), accent(0x3c, 0xb4, 0xf2);
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, window);
    p.setColor(QPalette::ToolTipBase, QColor(0x30, 0x36, 0x3f));
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::PlaceholderText, disabled);
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, QColor(0x2e, 0x34, 0x3c));
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, Qt::white);
    p.setColor(QPalette::Highlight, accent.darker(130));
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::Link, accent);
    p.setColor(QPalette::Mid, QColor(0x3a, 0x42, 0x4e));
    p.setColor(QPalette::Dark, QColor(0x14, 0x17, 0x1c));
    for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, disabled);
    app.setPalette(p);
    app.setWindowIcon(QIcon(QStringLiteral(":/slew/icons/slew.svg")));
}

} // namespace slew::ui
