// SPDX-License-Identifier: GPL-3.0-or-later
#include "ommkvn.h"

#include "gpfields.h"

#include "input/logtext.h"

#include <QStringList>

namespace slew::sky {
namespace {

// One message being read.
struct OpenMessage {
    GpEntry entry;
    bool started = false; // any line of it seen
    QString problem;      // a line of it that could not be read
    int problemLine = 0;
};

void finish(OpenMessage &m, ElementSetRead &result)
{
    if (!m.started)
        return;
    if (!m.problem.isEmpty()) {
        result.refusals.append({m.problemLine, 0, m.problem});
    } else {
        readGpEntry(m.entry, &result);
    }
    m = OpenMessage();
}

bool isKeyword(QStringView text)
{
    if (text.isEmpty())
        return false;
    for (const QChar c : text)
        if (!((c >= u'A' && c <= u'Z') || (c >= u'0' && c <= u'9') || c == u'_'))
            return false;
    return true;
}

// "15.5 [rev/day]" -> "15.5"
QStringView withoutUnit(QStringView value)
{
    const QStringView v = value.trimmed();
    if (v.endsWith(u']')) {
        const qsizetype open = v.lastIndexOf(u'[');
        if (open >= 0)
            return v.left(open).trimmed();
    }
    return v;
}

void writeLine(QString &text, const char *keyword, const QString &value)
{
    text += QString::fromLatin1(keyword).leftJustified(20) + QStringLiteral("= ") + value + u'\n';
}

} // namespace

ElementSetRead readOmmKvn(const QString &text)
{
    ElementSetRead result;
    const QList<QStringView> lines = QStringView(text).split(u'\n');
    OpenMessage message;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const int lineNumber = int(i + 1);
        QStringView line = lines[i].trimmed();
        if (i == 0 && line.startsWith(QChar(0xfeff)))
            line = line.mid(1).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1StringView("COMMENT")))
            continue;
        const qsizetype equals = line.indexOf(u'=');
        const QStringView keyword = equals < 0 ? QStringView() : line.left(equals).trimmed();
        if (!isKeyword(keyword)) {
            if (message.problem.isEmpty()) {
                message.problem = QStringLiteral("not a KEYWORD = value line: '%1'")
                                      .arg(input::loggableText(line.toString(), 40));
                message.problemLine = lineNumber;
            }
            message.started = true;
            continue;
        }
        const std::optional<GpField> field = gpFieldOfKeyword(keyword);
        // A new message: its version line, or a keyword the open one has.
        if (keyword == u"CCSDS_OMM_VERS" || (field && message.entry.has(*field)))
            finish(message, result);
        if (!message.started) {
            message.started = true;
            message.entry.line = lineNumber;
        }
        if (!field || line.mid(equals + 1).trimmed().isEmpty())
            continue;
        // Units follow numbers only: a name may end in brackets ("NOAA 16 [-]").
        const QStringView value = line.mid(equals + 1).trimmed();
        const bool number = gpFieldInfo(*field).kind == GpFieldInfo::Kind::Number
                            || gpFieldInfo(*field).kind == GpFieldInfo::Kind::Whole;
        message.entry.setText(*field, number ? withoutUnit(value) : value, lineNumber);
    }
    finish(message, result);
    return result;
}

QByteArray ommKvnText(const QList<ElementSet> &sets, const QDateTime &created)
{
    const QString createdText = created.toUTC().toString(QStringLiteral("yyyy-MM-ddTHH:mm:ss"));
    const GpField order[] = {GpField::ObjectName,     GpField::ObjectId,     GpField::CenterName,
                             GpField::RefFrame,       GpField::TimeSystem,   GpField::MeanElementTheory,
                             GpField::Epoch,          GpField::MeanMotion,   GpField::Eccentricity,
                             GpField::Inclination,    GpField::RaOfAscNode,  GpField::ArgOfPericenter,
                             GpField::MeanAnomaly,    GpField::EphemerisType, GpField::ClassificationType,
                             GpField::NoradCatId,     GpField::ElementSetNo, GpField::RevAtEpoch,
                             GpField::Bstar,          GpField::MeanMotionDot, GpField::MeanMotionDdot};
    QString text;
    for (qsizetype i = 0; i < sets.size(); ++i) {
        if (i > 0)
            text += u'\n';
        writeLine(text, "CCSDS_OMM_VERS", QStringLiteral("3.0"));
        writeLine(text, "CREATION_DATE", createdText);
        writeLine(text, "ORIGINATOR", QStringLiteral("Slew"));
        for (const GpField f : order)
            writeLine(text, gpFieldInfo(f).keyword, gpValueText(sets[i], f).text);
    }
    return text.toUtf8();
}

} // namespace slew::sky
