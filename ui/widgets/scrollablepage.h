// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A page of the window's tabs (and the control column) that scrolls when
// the window is smaller than the page's least size (a 1024x600 field
// screen), instead of that least size making the window too big for the
// screen. The page is given all the room there is and never less than its
// least size. QScrollArea's own resizing would hold a page with wrapping
// labels to its preferred height for its width, and so scroll at 1280x720
// where nothing needs to.

#include <QScrollArea>

namespace slew::ui {

class ScrollablePage : public QScrollArea {
    Q_OBJECT
public:
    explicit ScrollablePage(QWidget *page, QWidget *parent = nullptr);

    // The width the page needs not to scroll sideways.
    int pageLeastWidth() const;

protected:
    bool viewportEvent(QEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void fit(); // the page: the viewport's size, or its least size where that is more
};

// `page` in a frameless ScrollablePage.
ScrollablePage *scrollablePage(QWidget *page);

} // namespace slew::ui
