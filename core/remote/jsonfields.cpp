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
    const QJsonValue v = take(key, required);
    if (v.isUndefined())
        return std::nullopt;
    if (!v.isArray()) {
        fail(QStringLiteral("'%1' is not a list").arg(key));
        return std::nullopt;
    }
    const QJsonArray array = v.toArray();
    if (array.size() > maxItems) {
        fail(QStringLiteral("'%1' has %2 items, over %3").arg(key).arg(array.size()).arg(maxItems));
        return std::nullopt;
    }
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

} // namespace slew::remote
