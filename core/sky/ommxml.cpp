// SPDX-License-Identifier: GPL-3.0-or-later
#include "ommxml.h"

#include "gpfields.h"
#include "xmlscanner.h"

#include <QStringList>
#include <QXmlStreamWriter>

#include <optional>
#include <vector>

namespace slew::sky {
namespace {

// The sections of an OMM and the keywords Slew writes in each.
struct Section {
    const char *tag;
    QList<GpField> fields;
};

const QList<Section> &sections()
{
    static const QList<Section> all = {
        {"metadata",
         {GpField::ObjectName, GpField::ObjectId, GpField::CenterName, GpField::RefFrame, GpField::TimeSystem,
          GpField::MeanElementTheory}},
        {"meanElements",
         {GpField::Epoch, GpField::MeanMotion, GpField::Eccentricity, GpField::Inclination, GpField::RaOfAscNode,
          GpField::ArgOfPericenter, GpField::MeanAnomaly}},
        {"tleParameters",
         {GpField::EphemerisType, GpField::ClassificationType, GpField::NoradCatId, GpField::ElementSetNo,
          GpField::RevAtEpoch, GpField::Bstar, GpField::MeanMotionDot, GpField::MeanMotionDdot}},
    };
    return all;
}

// One <omm> being read: its keywords' texts, one after another in one
// string (kept from one OMM to the next, so reading allocates little), and
// where each starts.
struct OpenOmm {
    struct Field {
        GpField field;
        qsizetype from;
        qsizetype to;
        int line;
    };
    QString texts;
    std::vector<Field> fields;
    int line = 0;
    QString problem; // set when something inside cannot be read
    int problemLine = 0;

    void reset(int atLine)
    {
        texts.truncate(0);
        fields.clear();
        line = atLine;
        problem.clear();
    }
    void fail(const QString &why, int atLine)
    {
        if (problem.isEmpty()) {
            problem = why;
            problemLine = atLine;
        }
    }
    void add(GpField field, qsizetype from, int atLine)
    {
        fields.push_back({field, from, texts.size(), atLine});
    }
    void finish(ElementSetRead &result)
    {
        GpEntry entry;
        entry.line = line;
        for (const Field &f : fields) {
            if (entry.has(f.field))
                fail(QStringLiteral("%1 twice in one OMM").arg(QLatin1String(gpFieldInfo(f.field).keyword)), f.line);
            const QStringView text = QStringView(texts).mid(f.from, f.to - f.from).trimmed();
            if (!text.isEmpty())
                entry.setText(f.field, text, f.line);
        }
        if (!problem.isEmpty()) {
            result.refusals.append({problemLine, 0, problem});
            return;
        }
        readGpEntry(entry, &result);
    }
};

} // namespace

ElementSetRead readOmmXml(const QByteArray &bytes)
{
    ElementSetRead result;
    XmlScanner xml(bytes, kDeepestOmmXml);
    int depth = 0;
    int ommDepth = 0; // the depth of the <omm> open now; 0 outside one
    bool sawOmm = false;
    OpenOmm omm;
    // The keyword element being read: its field, where its text starts in
    // omm.texts, and its depth.
    int field = -1; // a GpField, or -1 outside a keyword
    qsizetype fieldStart = 0;
    int fieldLine = 0, fieldDepth = 0;
    while (true) {
        switch (xml.next()) {
        case XmlScanner::Token::StartElement: {
            ++depth;
            const QLatin1StringView name(xml.name());
            if (field >= 0) {
                omm.fail(QStringLiteral("%1 holds an element").arg(QLatin1String(gpFieldInfo(GpField(field)).keyword)),
                         xml.line());
                field = -1;
            }
            if (name == QLatin1StringView("omm")) {
                if (ommDepth > 0) {
                    result.refusals.append({xml.line(), 0, QStringLiteral("an <omm> inside an <omm>; the rest of the "
                                                                          "file is not read")});
                    return result;
                }
                sawOmm = true;
                ommDepth = depth;
                omm.reset(xml.line());
            } else if (ommDepth > 0) {
                field = int(gpFieldOfKeyword(name).value_or(GpField(-1)));
                fieldStart = omm.texts.size();
                fieldLine = xml.line();
                fieldDepth = depth;
            }
            break;
        }
        case XmlScanner::Token::Text: {
            // A reference or a character it refuses: the scanner is at Error
            // now, and the next token says so.
            xml.appendText(field >= 0 ? &omm.texts : nullptr);
            break;
        }
        case XmlScanner::Token::EndElement:
            if (field >= 0 && depth == fieldDepth) {
                omm.add(GpField(field), fieldStart, fieldLine);
                field = -1;
            }
            if (depth == ommDepth) {
                omm.finish(result);
                ommDepth = 0;
            }
            --depth;
            break;
        case XmlScanner::Token::End:
            if (!sawOmm)
                result.refusals.append({1, 0, QStringLiteral("the XML holds no <omm> element: not an OMM file")});
            return result;
        case XmlScanner::Token::Error:
            if (xml.refusedEntities()) {
                // Refused before anything it declares could be used.
                result.sets.clear();
                result.refusals = {{xml.line(), 0, xml.error()}};
                return result;
            }
            // What came before stays read; the break is named where it is.
            result.refusals.append({xml.line(), 0, QStringLiteral("the XML is not well-formed here (%1); the rest of "
                                                                  "the file is not read")
                                                       .arg(xml.error())});
            return result;
        }
    }
}

QByteArray ommXmlText(const QList<ElementSet> &sets, const QDateTime &created)
{
    QByteArray bytes;
    QXmlStreamWriter xml(&bytes);
    xml.setAutoFormatting(true);
    xml.setAutoFormattingIndent(1);
    xml.writeStartDocument();
    xml.writeStartElement(QStringLiteral("ndm"));
    xml.writeAttribute(QStringLiteral("xmlns:xsi"), QStringLiteral("http://www.w3.org/2001/XMLSchema-instance"));
    xml.writeAttribute(QStringLiteral("xsi:noNamespaceSchemaLocation"),
                       QStringLiteral("https://sanaregistry.org/r/ndmxml_unqualified/ndmxml-3.0.0-master-3.0.xsd"));
    const QString createdText = created.toUTC().toString(QStringLiteral("yyyy-MM-ddTHH:mm:ss"));
    for (const ElementSet &s : sets) {
        xml.writeStartElement(QStringLiteral("omm"));
        xml.writeAttribute(QStringLiteral("id"), QStringLiteral("CCSDS_OMM_VERS"));
        xml.writeAttribute(QStringLiteral("version"), QStringLiteral("3.0"));
        xml.writeStartElement(QStringLiteral("header"));
        xml.writeTextElement(QStringLiteral("CREATION_DATE"), createdText);
        xml.writeTextElement(QStringLiteral("ORIGINATOR"), QStringLiteral("Slew"));
        xml.writeEndElement();
        xml.writeStartElement(QStringLiteral("body"));
        xml.writeStartElement(QStringLiteral("segment"));
        for (const Section &section : sections()) {
            if (section.fields.first() == GpField::Epoch)
                xml.writeStartElement(QStringLiteral("data"));
            xml.writeStartElement(QLatin1String(section.tag));
            for (const GpField f : section.fields)
                xml.writeTextElement(QLatin1String(gpFieldInfo(f).keyword), gpValueText(s, f).text);
            xml.writeEndElement();
        }
        xml.writeEndElement(); // data
        xml.writeEndElement(); // segment
        xml.writeEndElement(); // body
        xml.writeEndElement(); // omm
    }
    xml.writeEndElement(); // ndm
    xml.writeEndDocument();
    return bytes;
}

} // namespace slew::sky
