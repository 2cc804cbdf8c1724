#pragma once
// The window's look: Fusion with a dark palette, so the plot, the charts and
// the controls read as one instrument panel and stay easy on the eyes in a
// dark shack at night.

class QApplication;

namespace slew::ui {

void applyOperatorTheme(QApplication &app);

} // namespace slew::ui
