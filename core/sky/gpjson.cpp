// SPDX-License-Identifier: GPL-3.0-or-later
#include "gpjson.h"

#include "gpfields.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>

namespace slew::sky {
namespace {

void readObject(const QJsonValue &value, int entryNumber, ElementSetRead &result)
{
    if (!value.isObject()) {
        result.refusals.append({0, entryNumber, QStringLiteral("not an object of OMM keywords")});
        return;
    }
    const QJsonObject object = value.toObject();
    GpEntry entry;
    entry.entry = entryNumber;
    QStringList texts; // what the entry's text values view
    texts.reserve(kGpFieldCount);
    for (int f = 0; f < kGpFieldCount; ++f) {
        const char *keyword = gpFieldInfo(GpField(f)).keyword;
        const QJsonValue v = object.value(QLatin1StringView(keyword));
        if (v.isString()) {
            texts << v.toString();
            if (!texts.last().trimmed().isEmpty())
                entry.setText(GpField(f), texts.last());
        } else if (v.isDouble()) {
            entry.setNumber(GpField(f), v.toDouble());
        } else if (!v.isUndefined() && !v.isNull()) {
            result.refusals.append({0, entryNumber, QStringLiteral("%1 is neither a number nor text")
                                                        .arg(QLatin1String(keyword))});
            return;
        }
    }
    readGpEntry(entry, &result);
}

// A JSON string: quotes, backslashes and control characters escaped.
QString jsonString(const QString &text)
{
    QString out = QStringLiteral("\"");
    for (const QChar c : text) {
        if (c == u'"' || c == u'\\')
            out += u'\\' + QString(c);
        else if (c.unicode() < 0x20)
            out += QStringLiteral("\\u%1").arg(c.unicode(), 4, 16, QLatin1Char('0'));
        else
            out += c;
    }
    return out + u'"';
}

} // namespace

ElementSetRead readGpJson(const QByteArray &bytes)
{
    ElementSetRead result;
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError) {
        // The line of the offset Qt names, so the message points into the file.
        const int line = int(bytes.left(error.offset).count('\n')) + 1;
        result.refusals.append({line, 0, QStringLiteral("not JSON: %1").arg(error.errorString())});
        return result;
    }
    if (document.isObject()) {
        readObject(document.object(), 1, result);
        return result;
    }
    const QJsonArray array = document.array();
    result.sets.reserve(array.size());
    for (qsizetype i = 0; i < array.size(); ++i)
        readObject(array.at(i), int(i + 1), result);
    return result;
}

QByteArray gpJsonText(const QList<ElementSet> &sets)
{
    QString text = QStringLiteral("[");
    for (qsizetype i = 0; i < sets.size(); ++i) {
        QStringList pairs;
        for (const GpField f : kGpFieldsWritten) {
            const GpValueText v = gpValueText(sets[i], f);
            pairs << jsonString(QLatin1String(gpFieldInfo(f).keyword)) + u':' + (v.isText ? jsonString(v.text) : v.text);
        }
        text += (i ? QStringLiteral(",\n{") : QStringLiteral("{")) + pairs.join(u',') + u'}';
    }
    return (text + QStringLiteral("]\n")).toUtf8();
}

} // namespace slew::sky
