// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The headers nearly every test includes, compiled once and reused by every
// test (tests/CMakeLists.txt, REUSE_FROM): a test file then compiles its
// own code rather than Qt's. Tests of the window use widgettestpch.h, as
// QtTest's own headers differ when Qt Widgets is linked. Every test file
// still includes what it uses.

#include <QByteArray>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QList>
#include <QObject>
#include <QPointF>
#include <QProcess>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QString>
#include <QStringList>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUrl>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
