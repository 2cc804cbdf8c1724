// SPDX-License-Identifier: GPL-3.0-or-later
#include "gpcsv.h"

#include "gpfields.h"

#include <QStringList>

#include <vector>

namespace slew::sky {
namespace {

// One record's fields, and the line each starts on. A field views the
// text, or, when it held an escaped quote, a string kept in `unescaped`.
struct Record {
    std::vector<QStringView> fields;
    std::vector<int> lines;
    QStringList unescaped;
    int line = 0;
    bool badQuote = false;
};

// Reads the record at `at` and moves `at` past its line end; counts lines.
class CsvCursor {
public:
    explicit CsvCursor(const QString &text) : m_text(text)
    {
        if (!m_text.isEmpty() && m_text[0] == QChar(0xfeff))
            m_at = 1;
    }
    bool atEnd() const { return m_at >= m_text.size(); }
    int line() const { return m_line; }

    void next(Record *r)
    {
        r->fields.clear();
        r->lines.clear();
        r->unescaped.clear();
        r->line = m_line;
        r->badQuote = false;
        const qsizetype size = m_text.size();
        const QChar *data = m_text.constData();
        while (true) {
            r->lines.push_back(m_line);
            if (m_at < size && data[m_at] == u'"') {
                // A quoted field: up to the quote not doubled; it may hold
                // commas and line ends.
                const qsizetype start = ++m_at;
                bool escaped = false;
                while (m_at < size) {
                    if (data[m_at] == u'"') {
                        if (m_at + 1 < size && data[m_at + 1] == u'"') {
                            escaped = true;
                            m_at += 2;
                            continue;
                        }
                        break;
                    }
                    if (data[m_at] == u'\n')
                        ++m_line;
                    ++m_at;
                }
                QStringView field(data + start, m_at - start);
                if (m_at >= size)
                    r->badQuote = true;
                else
                    ++m_at; // the closing quote
                if (escaped) {
                    r->unescaped << field.toString().replace(QStringLiteral("\"\""), QStringLiteral("\""));
                    field = r->unescaped.last();
                }
                r->fields.push_back(field);
                // Only a comma or the line's end may follow a closing quote.
                if (m_at < size && data[m_at] != u',' && data[m_at] != u'\r' && data[m_at] != u'\n')
                    r->badQuote = true;
                while (m_at < size && data[m_at] != u',' && data[m_at] != u'\n')
                    ++m_at;
            } else {
                const qsizetype start = m_at;
                while (m_at < size && data[m_at] != u',' && data[m_at] != u'\n')
                    ++m_at;
                qsizetype end = m_at;
                if (end > start && data[end - 1] == u'\r')
                    --end;
                r->fields.push_back(QStringView(data + start, end - start));
            }
            if (m_at < size && data[m_at] == u',') {
                ++m_at;
                continue;
            }
            if (m_at < size) { // the line's end
                ++m_at;
                ++m_line;
            }
            return;
        }
    }

private:
    const QString &m_text;
    qsizetype m_at = 0;
    int m_line = 1;
};

bool isBlank(const Record &r)
{
    return r.fields.size() == 1 && r.fields[0].trimmed().isEmpty();
}

QString csvField(const QString &text)
{
    if (!text.contains(u',') && !text.contains(u'"') && !text.contains(u'\n') && !text.contains(u'\r'))
        return text;
    return u'"' + QString(text).replace(QStringLiteral("\""), QStringLiteral("\"\"")) + u'"';
}

} // namespace

ElementSetRead readGpCsv(const QString &text)
{
    ElementSetRead result;
    CsvCursor cursor(text);
    Record record;
    // The header: the first line that is not blank.
    do {
        if (cursor.atEnd())
            return result;
        cursor.next(&record);
    } while (isBlank(record));
    std::vector<int> fieldOfColumn(record.fields.size(), -1);
    bool named[kGpFieldCount] = {};
    for (size_t c = 0; c < record.fields.size(); ++c) {
        if (const std::optional<GpField> f = gpFieldOfKeyword(record.fields[c].trimmed())) {
            if (named[int(*f)]) {
                result.refusals.append({record.line, 0, QStringLiteral("the header names %1 twice")
                                                            .arg(QLatin1String(gpFieldInfo(*f).keyword))});
                return result;
            }
            fieldOfColumn[c] = int(*f);
            named[int(*f)] = true;
        }
    }
    QStringList missing;
    for (int f = 0; f < kGpFieldCount; ++f)
        if (gpFieldInfo(GpField(f)).required && !named[f])
            missing << QLatin1String(gpFieldInfo(GpField(f)).keyword);
    if (!missing.isEmpty()) {
        result.refusals.append({record.line, 0, QStringLiteral("the header has no %1 column: not a GP CSV file")
                                                    .arg(missing.join(QStringLiteral(", ")))});
        return result;
    }

    const size_t columns = fieldOfColumn.size();
    result.sets.reserve(text.size() / 128); // a row is some 150 characters
    while (!cursor.atEnd()) {
        cursor.next(&record);
        if (isBlank(record))
            continue;
        if (record.badQuote) {
            result.refusals.append({record.line, 0, QStringLiteral("a quoted field is not closed, or text follows its "
                                                                   "closing quote")});
            continue;
        }
        if (record.fields.size() != columns) {
            result.refusals.append({record.line, 0, QStringLiteral("a %1 row: %2 fields where the header has %3")
                                                        .arg(record.fields.size() < columns ? QStringLiteral("short")
                                                                                            : QStringLiteral("long"))
                                                        .arg(record.fields.size())
                                                        .arg(columns)});
            continue;
        }
        GpEntry entry;
        entry.line = record.line;
        for (size_t c = 0; c < columns; ++c) {
            if (fieldOfColumn[c] < 0)
                continue;
            // An empty cell is a value not given (Space-Track leaves them so).
            const QStringView cell = record.fields[c].trimmed();
            if (!cell.isEmpty())
                entry.setText(GpField(fieldOfColumn[c]), cell, record.lines[c]);
        }
        readGpEntry(entry, &result);
    }
    return result;
}

QByteArray gpCsvText(const QList<ElementSet> &sets)
{
    QStringList header;
    for (const GpField f : kGpFieldsWritten)
        header << QLatin1String(gpFieldInfo(f).keyword);
    QString text = header.join(u',') + QStringLiteral("\r\n");
    for (const ElementSet &s : sets) {
        QStringList row;
        for (const GpField f : kGpFieldsWritten) {
            const GpValueText v = gpValueText(s, f);
            row << (v.isText ? csvField(v.text) : v.text);
        }
        text += row.join(u',') + QStringLiteral("\r\n");
    }
    return text.toUtf8();
}

} // namespace slew::sky
