#pragma once
// `slew --screenshot FILE.png`: once the window has had time to settle
// (connect, probe, draw a few polls), render it to a PNG and quit. Rendering
// goes through QWidget::grab, so it works on the offscreen platform.

#include <QString>

class QWidget;

namespace slew::ui {

// Exits the event loop with 0 when the file was written, 1 otherwise.
void scheduleWindowSnapshot(QWidget *window, const QString &path, int settleMs);

} // namespace slew::ui
