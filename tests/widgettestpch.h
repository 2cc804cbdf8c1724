// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// testpch.h for the tests that link the window (slewui): the same headers,
// compiled with Qt Widgets' definitions, and the widgets they look into.

#include "testpch.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QWidget>
