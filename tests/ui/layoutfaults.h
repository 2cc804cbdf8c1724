// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What an operator sees as a broken layout, found by walking a window's
// widgets on a real X11 server, once the layout has settled (posted layout
// requests sent round after round, more rounds than a widget tree is deep):
// - two visible widgets of one layout on top of each other;
// - a widget squeezed below the smallest size its layout promised it;
// - a label, a button or a field whose text does not fit (cut, not elided
//   on purpose).
// Each fault names the widgets by class and objectName, so a failing test
// says where to look.

#include <QStringList>

class QWidget;

QStringList layoutFaults(QWidget *top);
