// SPDX-License-Identifier: GPL-3.0-or-later
#include "jsonfields.h"

#include "input/logtext.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>

namespace slew::remote {

std::optional<JsonFields> JsonFields::parse(const QByteArray &payload, qsizetype maxBytes, QString *error)
{
    if (payload.size() > maxBytes) {
        *error = QStringLiteral("%1 bytes, over the %2 a message may have").arg(payload.size()).arg(maxBytes);
        return std::nullopt;
    }
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(payload, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        *error = QStringLiteral("not JSON (%1 at byte %2)").arg(parseError.errorString()).arg(parseError.offset);
        return std::nullopt;
    }
    if (!doc.isObject()) {
        *error = QStringLiteral("not a JSON object");
        return std::nullopt;
    }
    return JsonFields(doc.object());
}

void JsonFields::fail(const QString &error)
{
    if (m_error.isEmpty())
        m_error = error;
}

bool JsonFields::isShowable(const QString &text, int maxChars)
{
    if (text.size() > maxChars)
        return false;
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if (u < 0x20 || (u >= 0x7f && u < 0xa0) || u == 0x2028 || u == 0x2029)
            return false;
    }
    return true;
}

QJsonValue JsonFields::take(const QString &key, bool required)
{
    m_named.insert(key);
    const QJsonValue value = m_object.value(key);
    if (value.isUndefined() && required)
        fail(QStringLiteral("'%1' is missing").arg(key));
    return value;
}

std::optional<QJsonArray> JsonFields::takeList(const QString &key, int maxItems, bool required)
{
    const QJsonValue v = take(key, required);
    if (v.isUndefined())
        return std::nullopt;
    if (!v.isArray()) {
        fail(QStringLiteral("'%1' is not a list").arg(key));
        return std::nullopt;
    }
    if (v.toArray().size() > maxItems) {
        fail(QStringLiteral("'%1' has %2 items, over the %3 it may have").arg(key).arg(v.toArray().size()).arg(maxItems));
        return std::nullopt;
    }
    return v.toArray();
}

std::optional<double> JsonFields::number(const QString &key, const input::NumberRange &range, bool required)
{
    const QJsonValue v = take(key, required);
    if (v.isUndefined())
        return std::nullopt;
    if (!v.isDouble()) {
        fail(QStringLiteral("'%1' is not a number").arg(key));
        return std::nullopt;
    }
    QString why;
    if (!input::checkNumber(v.toDouble(), range, &why)) {
        fail(QStringLiteral("'%1': %2").arg(key, why));
        return std::nullopt;
    }
    return v.toDouble();
}

std::optional<qint64> JsonFields::whole(const QString &key, qint64 min, qint64 max, bool required)
{
    const QJsonValue v = take(key, required);
    if (v.isUndefined())
        return std::nullopt;
    const double d = v.toDouble(std::nan(""));
    if (!v.isDouble() || !std::isfinite(d) || d != std::floor(d)) {
        fail(QStringLiteral("'%1' is not a whole number").arg(key));
        return std::nullopt;
    }
    if (d < double(min) || d > double(max)) {
        fail(QStringLiteral("'%1': %2 is outside %3..%4").arg(key).arg(d, 0, 'f', 0).arg(min).arg(max));
        return std::nullopt;
    }
    return qint64(d);
}

std::optional<QString> JsonFields::text(const QString &key, int maxChars, bool required)
{
    const QJsonValue v = take(key, required);
    if (v.isUndefined())
        return std::nullopt;
    if (!v.isString()) {
        fail(QStringLiteral("'%1' is not text").arg(key));
        return std::nullopt;
    }
    const QString s = v.toString();
    if (!isShowable(s, maxChars)) {
        fail(QStringLiteral("'%1' is over %2 characters or has control characters in it: '%3'")
                 .arg(key)
                 .arg(maxChars)
                 .arg(input::loggableText(s, 60)));
        return std::nullopt;
    }
    return s;
}

std::optional<bool> JsonFields::flag(const QString &key, bool required)
{
    const QJsonValue v = take(key, required);
    if (v.isUndefined())
        return std::nullopt;
    if (!v.isBool()) {
        fail(QStringLiteral("'%1' is not true or false").arg(key));
        return std::nullopt;
    }
    return v.toBool();
}

std::optional<QStringList> JsonFields::texts(const QString &key, int maxItems, int maxChars, bool required)
{
    const std::optional<QJsonArray> list = takeList(key, maxItems, required);
    if (!list)
        return std::nullopt;
    const QJsonArray &array = *list;
    QStringList out;
    for (const QJsonValue &item : array) {
        if (!item.isString() || !isShowable(item.toString(), maxChars)) {
            fail(QStringLiteral("'%1' holds an item that is not text of at most %2 characters without control "
                                "characters")
                     .arg(key)
                     .arg(maxChars));
            return std::nullopt;
        }
        out << item.toString();
    }
    return out;
}

bool JsonFields::noOthers()
{
    for (auto it = m_object.constBegin(); it != m_object.constEnd(); ++it) {
        if (!m_named.contains(it.key())) {
            fail(QStringLiteral("unknown field '%1'").arg(input::loggableText(it.key(), 40)));
            return false;
        }
    }
    return ok();
}

std::optional<QJsonObject> JsonFields::object(const QString &key, bool required)
{
    const QJsonValue value = take(key, required);
    if (value.isUndefined())
        return std::nullopt;
    if (!value.isObject()) {
        fail(QStringLiteral("'%1' is not an object").arg(key));
        return std::nullopt;
    }
    return value.toObject();
}

std::optional<QList<QJsonObject>> JsonFields::objects(const QString &key, int maxItems, bool required)
{
    const std::optional<QJsonArray> list = takeList(key, maxItems, required);
    if (!list)
        return std::nullopt;
    const QJsonArray &array = *list;
    QList<QJsonObject> out;
    out.reserve(array.size());
    for (qsizetype i = 0; i < array.size(); ++i) {
        if (!array.at(i).isObject()) {
            fail(QStringLiteral("'%1' item %2 is not an object").arg(key).arg(i + 1));
            return std::nullopt;
        }
        out.append(array.at(i).toObject());
    }
    return out;
}

std::optional<QList<QPointF>> JsonFields::points(const QString &key, int maxItems, bool required)
{
    const std::optional<QJsonArray> list = takeList(key, maxItems, required);
    if (!list)
        return std::nullopt;
    const QJsonArray &array = *list;
    QList<QPointF> out;
    out.reserve(array.size());
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QJsonArray pair = array.at(i).toArray();
        const double az = pair.size() == 2 ? pair.at(0).toDouble(std::nan("")) : std::nan("");
        const double el = pair.size() == 2 ? pair.at(1).toDouble(std::nan("")) : std::nan("");
        if (!array.at(i).isArray() || !std::isfinite(az) || !std::isfinite(el) || az < -360 || az > 720 || el < -90
            || el > 180) {
            fail(QStringLiteral("'%1' point %2 is not [az, el] with az in -360..720 and el in -90..180").arg(key).arg(i + 1));
            return std::nullopt;
        }
        out.append(QPointF(az, el));
    }
    return out;
}

} // namespace slew::remote
