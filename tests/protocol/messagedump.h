#pragma once
// A readable one-line form of a parsed message, so test tables can state the
// expected result as plain text: `azimuth=123.1|` (the bar: the line ended).

#include "protocol/message.h"

#include <QString>
#include <QStringList>

inline QString dumpMessage(const slew::protocol::Message &m)
{
    using slew::protocol::Op;
    QString s = QString::fromLatin1(slew::protocol::describe(m.op));
    if (m.index >= 0)
        s += QStringLiteral("#%1").arg(m.index);
    if (m.op == Op::Encoders && m.hasValue) {
        s += QStringLiteral("=%1,%2,%3,%4")
                 .arg(m.encoders[0], 0, 'g', 12)
                 .arg(m.encoders[1], 0, 'g', 12)
                 .arg(m.encoders[2], 0, 'g', 12)
                 .arg(m.encoders[3], 0, 'g', 12);
    } else if (m.hasValue) {
        s += QStringLiteral("=%1").arg(m.value, 0, 'g', 12);
    }
    if (!m.text.isEmpty())
        s += QStringLiteral(" '%1'").arg(QString::fromLatin1(m.text.view().toByteArray()));
    if (m.lineEnd)
        s += QLatin1Char('|');
    return s;
}

template <typename Parser>
QStringList parseAll(Parser &parser, QByteArrayView bytes)
{
    QStringList out;
    parser.feed(bytes, [&](const slew::protocol::Message &m) { out << dumpMessage(m); });
    return out;
}
