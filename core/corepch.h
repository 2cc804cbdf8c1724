// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Qt and standard headers most of slewcore includes, compiled once for
// the whole library (target_precompile_headers in core/CMakeLists.txt)
// rather than parsed again for each of its 180-odd files. Every file still
// includes what it uses: this only makes the second time free.

#include <QByteArray>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QHostAddress>
#include <QIODevice>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QList>
#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QString>
#include <QStringList>
#include <QTcpSocket>
#include <QTimer>
#include <QUrl>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <vector>
