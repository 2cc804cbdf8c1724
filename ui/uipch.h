// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Qt headers most of slewui includes, compiled once for the library
// (target_precompile_headers in ui/CMakeLists.txt). Every file still
// includes what it uses: this only makes the second time free.

#include "corepch.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPainter>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QWidget>
