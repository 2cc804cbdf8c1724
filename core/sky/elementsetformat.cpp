// SPDX-License-Identifier: GPL-3.0-or-later
#include "elementsetformat.h"

#include "gpcsv.h"
#include "gpfields.h"
#include "gpjson.h"
#include "ommkvn.h"
#include "ommxml.h"
#include "tleformat.h"

#include "input/boundedfile.h"
#include "input/logtext.h"

namespace slew::sky {
namespace {

struct FormName {
    ElementSetForm form;
    const char *name;   // in messages
    const char *option; // in --format
};
constexpr FormName kForms[] = {{ElementSetForm::Tle, "TLE", "tle"},
                               {ElementSetForm::Csv, "CSV", "csv"},
                               {ElementSetForm::OmmXml, "OMM XML", "xml"},
                               {ElementSetForm::Json, "JSON", "json"},
                               {ElementSetForm::OmmKvn, "OMM KVN", "kvn"}};

// The first line that is not blank, after a byte-order mark.
QByteArray firstLine(const QByteArray &bytes)
{
    qsizetype at = bytes.startsWith("\xef\xbb\xbf") ? 3 : 0;
    while (true) {
        const qsizetype end = bytes.indexOf('\n', at);
        const QByteArray line = bytes.mid(at, end < 0 ? -1 : end - at).trimmed();
        if (!line.isEmpty() || end < 0)
            return line;
        at = end + 1;
    }
}

bool startsKvn(const QByteArray &line)
{
    if (line.startsWith("CCSDS_OMM_VERS") || line.startsWith("COMMENT"))
        return true;
    const qsizetype equals = line.indexOf('=');
    return equals > 0 && gpFieldOfKeyword(QString::fromLatin1(line.left(equals).trimmed()));
}

bool startsCsv(const QByteArray &line)
{
    if (!line.contains(','))
        return false;
    for (const QByteArray &cell : line.split(',')) {
        QByteArray name = cell.trimmed();
        if (name.startsWith('"') && name.endsWith('"') && name.size() >= 2)
            name = name.mid(1, name.size() - 2);
        if (gpFieldOfKeyword(QString::fromLatin1(name)))
            return true;
    }
    return false;
}

} // namespace

QString formName(ElementSetForm form)
{
    for (const FormName &f : kForms)
        if (f.form == form)
            return QLatin1String(f.name);
    return {};
}

std::optional<ElementSetForm> formFromName(QStringView name)
{
    for (const FormName &f : kForms)
        if (name.trimmed().compare(QLatin1StringView(f.option), Qt::CaseInsensitive) == 0)
            return f.form;
    return std::nullopt;
}

ElementSetForm recogniseForm(const QByteArray &bytes)
{
    for (qsizetype i = bytes.startsWith("\xef\xbb\xbf") ? 3 : 0; i < bytes.size(); ++i) {
        const char c = bytes[i];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
            continue;
        if (c == '<')
            return ElementSetForm::OmmXml;
        if (c == '[' || c == '{')
            return ElementSetForm::Json;
        break;
    }
    const QByteArray line = firstLine(bytes);
    if (startsKvn(line))
        return ElementSetForm::OmmKvn;
    if (startsCsv(line))
        return ElementSetForm::Csv;
    return ElementSetForm::Tle;
}

ElementSetText readElementSets(const QByteArray &bytes)
{
    ElementSetText text;
    text.form = recogniseForm(bytes);
    switch (text.form) {
    case ElementSetForm::Tle: text.read = readTleText(QString::fromUtf8(bytes)); break;
    case ElementSetForm::Csv: text.read = readGpCsv(QString::fromUtf8(bytes)); break;
    case ElementSetForm::OmmXml: text.read = readOmmXml(bytes); break;
    case ElementSetForm::Json: text.read = readGpJson(bytes); break;
    case ElementSetForm::OmmKvn: text.read = readOmmKvn(QString::fromUtf8(bytes)); break;
    }
    return text;
}

ElementSetFile readElementSetFile(const QString &path)
{
    ElementSetFile file;
    const input::BoundedRead read = input::readBoundedFile(path, kLargestElementFile);
    if (!read.ok()) {
        file.error = read.error;
        return file;
    }
    const ElementSetText text = readElementSets(read.bytes);
    file.form = text.form;
    file.refusals = text.read.refusals;
    file.sets = mergeByCatalogueNumber(text.read.sets);
    file.duplicates = int(text.read.sets.size() - file.sets.size());
    return file;
}

WrittenElementSets writeElementSets(const QList<ElementSet> &sets, ElementSetForm form, const QDateTime &created)
{
    WrittenElementSets written;
    switch (form) {
    case ElementSetForm::Tle: {
        QString text;
        for (const ElementSet &s : sets) {
            QString why;
            if (const std::optional<QString> lines = tleText(s, &why))
                text += *lines;
            else
                written.left << QStringLiteral("%1 (%2): %3")
                                    .arg(input::loggableText(s.displayName(), 40))
                                    .arg(s.catalogueNumber)
                                    .arg(why);
        }
        written.bytes = text.toUtf8();
        break;
    }
    case ElementSetForm::Csv: written.bytes = gpCsvText(sets); break;
    case ElementSetForm::OmmXml: written.bytes = ommXmlText(sets, created); break;
    case ElementSetForm::Json: written.bytes = gpJsonText(sets); break;
    case ElementSetForm::OmmKvn: written.bytes = ommKvnText(sets, created); break;
    }
    return written;
}

} // namespace slew::sky
