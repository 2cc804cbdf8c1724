// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading a JSON message from the broker under the input rules: one object
// of bounded size; every field of the right type, numbers finite and in
// range, text bounded and free of control characters; a field nobody
// asked for is an error too. The first fault is kept, naming its field;
// the caller drops the whole message when there is one. Pure code.

#include "input/finitenumber.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QList>
#include <QPointF>
#include <QSet>
#include <QString>

#include <optional>

namespace slew::remote {

class JsonFields {
public:
    // The object `payload` holds, or nothing with *error (not JSON, not an
    // object, larger than maxBytes).
    static std::optional<JsonFields> parse(const QByteArray &payload, qsizetype maxBytes, QString *error);
    explicit JsonFields(QJsonObject object) : m_object(std::move(object)) {}

    bool has(const QString &key) const { return m_object.contains(key); }
    // A missing field gives nothing, an error only when `required`.
    std::optional<double> number(const QString &key, const input::NumberRange &range, bool required = false);
    std::optional<qint64> whole(const QString &key, qint64 min, qint64 max, bool required = false);
    std::optional<QString> text(const QString &key, int maxChars, bool required = false);
    std::optional<bool> flag(const QString &key, bool required = false);
    // An array of texts, at most maxItems of at most maxChars each.
    std::optional<QStringList> texts(const QString &key, int maxItems, int maxChars, bool required = false);
    // An object of its own, to be read with JsonFields of its own (a
    // reply's preview).
    std::optional<QJsonObject> object(const QString &key, bool required = false);
    // A list of at most maxItems objects, each to be read with JsonFields
    // of its own (a schedule's passes).
    std::optional<QList<QJsonObject>> objects(const QString &key, int maxItems, bool required = false);
    // A list of at most maxItems points, each [az, el] with both in range
    // (a plan's path): azimuth -360..720, elevation -90..180.
    std::optional<QList<QPointF>> points(const QString &key, int maxItems, bool required = false);
    // Fails on any field no call above has named.
    bool noOthers();

    bool ok() const { return m_error.isEmpty(); }
    QString error() const { return m_error; }
    void fail(const QString &error);

    // Text safe to show: no control characters, at most maxChars.
    static bool isShowable(const QString &text, int maxChars);

private:
    QJsonValue take(const QString &key, bool required);
    // A list of at most maxItems, or nothing (and the fault when it is not).
    std::optional<QJsonArray> takeList(const QString &key, int maxItems, bool required);

    QJsonObject m_object;
    QSet<QString> m_named;
    QString m_error;
};

} // namespace slew::remote
