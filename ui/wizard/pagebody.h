// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where a wizard page puts its widgets: a widget inside a scroll area that
// fills the page. At the wizard's own size every page fits and no scroll bar
// shows; on a smaller screen, or once a page has grown (a tuning run's
// figures, a long write-back list), the page scrolls instead of squeezing
// its widgets on top of each other.

class QWidget;
class QWizardPage;

namespace slew::ui {

// Makes the scroll area on the page and returns the widget to lay out.
QWidget *makePageBody(QWizardPage *page);

} // namespace slew::ui
