#pragma once
// The window's look: Fusion with a dark palette, so the plot, the charts and
// the controls read as one instrument panel and stay easy on the eyes in a
// dark shack at night.

#include <QString>

class QApplication;

namespace slew::ui {

void applyOperatorTheme(QApplication &app);

// The tones a message is shown in, each written once, so the operator
// learns them once: every refusal in one red (a move the gate refused, a
// field that will not be taken), every warning in one amber (a link down,
// a radio not answering: something to look at, nothing refused).
namespace tone {
inline constexpr char kRefused[] = "#e54848";
inline constexpr char kWarning[] = "#f2a33c";
} // namespace tone

// A label's style sheet in that tone.
inline QString refusedText()
{
    return QStringLiteral("color:%1;").arg(QLatin1String(tone::kRefused));
}
inline QString warningText()
{
    return QStringLiteral("color:%1;").arg(QLatin1String(tone::kWarning));
}
// A field's frame in the refusal tone: what is typed there will not be taken.
inline QString refusedField(const char *widget = "QLineEdit")
{
    return QStringLiteral("%1{border:2px solid %2;}").arg(QLatin1String(widget), QLatin1String(tone::kRefused));
}

} // namespace slew::ui
