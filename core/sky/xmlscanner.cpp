// SPDX-License-Identifier: GPL-3.0-or-later
#include "xmlscanner.h"

#include <algorithm>
#include <cstring>

namespace slew::sky {
namespace {

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

bool isNameStart(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == ':' || (unsigned char)c >= 0x80;
}

bool isNameChar(char c)
{
    return isNameStart(c) || (c >= '0' && c <= '9') || c == '-' || c == '.';
}

// The part of a qualified name after its prefix.
QByteArrayView localName(QByteArrayView name)
{
    const qsizetype colon = name.lastIndexOf(':');
    return colon < 0 ? name : name.sliced(colon + 1);
}

// A character XML 1.0 allows in a document.
bool isXmlChar(char32_t c)
{
    return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD)
           || (c >= 0x10000 && c <= 0x10FFFF);
}

QString shown(QByteArrayView text)
{
    QString out;
    for (const char c : text.first(std::min<qsizetype>(text.size(), 30)))
        out += (c >= 0x20 && c < 0x7f) ? QChar(c) : QChar(u'?');
    return out;
}

} // namespace

XmlScanner::XmlScanner(QByteArrayView bytes, int deepest)
    : m_bytes(bytes), m_deepest(deepest)
{
    if (m_bytes.startsWith("\xef\xbb\xbf"))
        m_at = 3;
}

XmlScanner::Token XmlScanner::fail(const QString &why)
{
    m_error = why;
    m_state = Token::Error;
    return m_state;
}

XmlScanner::Token XmlScanner::refuseEntities(const QString &why)
{
    m_refusedEntities = true;
    return fail(why);
}

void XmlScanner::countLines(qsizetype from, qsizetype to)
{
    m_line += int(std::count(m_bytes.data() + from, m_bytes.data() + to, '\n'));
}

void XmlScanner::skipSpace()
{
    while (m_at < m_bytes.size() && isSpace(m_bytes[m_at])) {
        if (m_bytes[m_at] == '\n')
            ++m_line;
        ++m_at;
    }
}

bool XmlScanner::readName(QByteArrayView *name)
{
    const qsizetype start = m_at;
    if (m_at >= m_bytes.size() || !isNameStart(m_bytes[m_at]))
        return false;
    while (m_at < m_bytes.size() && isNameChar(m_bytes[m_at]))
        ++m_at;
    *name = m_bytes.sliced(start, m_at - start);
    return true;
}

bool XmlScanner::skipPast(QByteArrayView end)
{
    const qsizetype found = m_bytes.indexOf(end, m_at);
    if (found < 0)
        return false;
    countLines(m_at, found);
    m_at = found + end.size();
    return true;
}

XmlScanner::Token XmlScanner::next()
{
    if (m_state == Token::End || m_state == Token::Error)
        return m_state;
    if (m_pendingEnd) {
        m_pendingEnd = false;
        m_name = localName(m_open.back());
        m_open.pop_back();
        return m_state = Token::EndElement;
    }
    while (true) {
        m_tokenLine = m_line;
        if (m_at >= m_bytes.size()) {
            if (!m_open.empty())
                return fail(QStringLiteral("the file ends inside <%1>").arg(shown(m_open.back())));
            if (!m_rootSeen)
                return fail(QStringLiteral("no element in the file"));
            return m_state = Token::End;
        }
        if (m_bytes[m_at] != '<') {
            // Text up to the next tag.
            const qsizetype start = m_at;
            const char *lt = static_cast<const char *>(std::memchr(m_bytes.data() + m_at, '<', size_t(m_bytes.size() - m_at)));
            const qsizetype end = lt ? lt - m_bytes.data() : m_bytes.size();
            countLines(start, end);
            m_at = end;
            m_text = m_bytes.sliced(start, end - start);
            m_textIsCdata = false;
            if (atRootLevel()) {
                for (const char c : m_text)
                    if (!isSpace(c))
                        return fail(QStringLiteral("text outside the root element"));
                continue;
            }
            return m_state = Token::Text;
        }
        if (m_at + 1 < m_bytes.size() && m_bytes[m_at + 1] == '/')
            return endTag();
        if (m_at + 1 < m_bytes.size() && (m_bytes[m_at + 1] == '!' || m_bytes[m_at + 1] == '?')) {
            if (const std::optional<Token> t = markup())
                return *t;
            continue; // a comment or a processing instruction
        }
        return startTag();
    }
}

std::optional<XmlScanner::Token> XmlScanner::markup()
{
    const QByteArrayView rest = m_bytes.sliced(m_at);
    if (rest.startsWith("<!--")) {
        m_at += 4;
        if (!skipPast("-->"))
            return fail(QStringLiteral("a comment is not closed"));
        return std::nullopt;
    }
    if (rest.startsWith("<![CDATA[")) {
        if (atRootLevel())
            return fail(QStringLiteral("CDATA outside the root element"));
        const qsizetype start = m_at + 9;
        m_at = start;
        if (!skipPast("]]>"))
            return fail(QStringLiteral("a CDATA section is not closed"));
        m_text = m_bytes.sliced(start, m_at - 3 - start);
        m_textIsCdata = true;
        return m_state = Token::Text;
    }
    if (rest.startsWith("<!DOCTYPE"))
        return refuseEntities(QStringLiteral("the XML has a document type declaration (<!DOCTYPE>), which an OMM never needs: "
                                   "refused, nothing read"));
    if (rest.startsWith("<?")) {
        const qsizetype start = m_at + 2;
        m_at = start;
        if (!skipPast("?>"))
            return fail(QStringLiteral("a processing instruction is not closed"));
        const QByteArrayView body = m_bytes.sliced(start, m_at - 2 - start);
        if (body.startsWith("xml") && (body.size() == 3 || isSpace(body[3]))) {
            // The declaration: first in the file, and UTF-8 (the default) only.
            if (start != (m_bytes.startsWith("\xef\xbb\xbf") ? 5 : 2))
                return fail(QStringLiteral("an XML declaration that is not at the start"));
            const qsizetype encoding = body.indexOf("encoding");
            if (encoding >= 0) {
                const QByteArray value = body.sliced(encoding + 8).toByteArray().toUpper();
                if (!value.contains("UTF-8") && !value.contains("UTF8") && !value.contains("US-ASCII"))
                    return fail(QStringLiteral("the XML is not in UTF-8; only UTF-8 is read"));
            }
        }
        return std::nullopt;
    }
    return fail(QStringLiteral("markup that is not an element, a comment, CDATA or a processing instruction"));
}

XmlScanner::Token XmlScanner::startTag()
{
    ++m_at; // '<'
    QByteArrayView name;
    if (!readName(&name))
        return fail(QStringLiteral("'<' that starts no element"));
    if (atRootLevel()) {
        if (m_rootSeen)
            return fail(QStringLiteral("a second root element <%1>").arg(shown(name)));
        m_rootSeen = true;
    }
    // Attributes: read for well-formedness, not kept.
    while (true) {
        const qsizetype before = m_at;
        skipSpace();
        if (m_at >= m_bytes.size())
            return fail(QStringLiteral("the file ends inside a tag"));
        const char c = m_bytes[m_at];
        if (c == '>' || (c == '/' && m_at + 1 < m_bytes.size() && m_bytes[m_at + 1] == '>'))
            break;
        QByteArrayView attribute;
        if (m_at == before || !readName(&attribute))
            return fail(QStringLiteral("a malformed attribute in <%1>").arg(shown(name)));
        skipSpace();
        if (m_at >= m_bytes.size() || m_bytes[m_at] != '=')
            return fail(QStringLiteral("an attribute without a value in <%1>").arg(shown(name)));
        ++m_at;
        skipSpace();
        if (m_at >= m_bytes.size() || (m_bytes[m_at] != '"' && m_bytes[m_at] != '\''))
            return fail(QStringLiteral("an attribute value without quotes in <%1>").arg(shown(name)));
        const char quote = m_bytes[m_at++];
        const qsizetype close = m_bytes.indexOf(quote, m_at);
        if (close < 0 || m_bytes.sliced(m_at, close - m_at).contains('<'))
            return fail(QStringLiteral("an attribute value not closed in <%1>").arg(shown(name)));
        countLines(m_at, close);
        m_at = close + 1;
    }
    if (int(m_open.size()) >= m_deepest)
        return fail(QStringLiteral("elements nested deeper than %1: not an OMM; the rest of the file is not read")
                        .arg(m_deepest));
    m_open.push_back(name);
    if (m_bytes[m_at] == '/') {
        m_at += 2;
        m_pendingEnd = true;
    } else {
        ++m_at;
    }
    m_name = localName(name);
    return m_state = Token::StartElement;
}

XmlScanner::Token XmlScanner::endTag()
{
    m_at += 2; // "</"
    QByteArrayView name;
    if (!readName(&name))
        return fail(QStringLiteral("'</' that names no element"));
    skipSpace();
    if (m_at >= m_bytes.size() || m_bytes[m_at] != '>')
        return fail(QStringLiteral("an end tag </%1 not closed by '>'").arg(shown(name)));
    ++m_at;
    if (m_open.empty() || m_open.back() != name)
        return fail(QStringLiteral("</%1> where %2").arg(shown(name), m_open.empty() ? QStringLiteral("no element is open")
                                                                                  : QStringLiteral("<%1> is open").arg(shown(m_open.back()))));
    m_open.pop_back();
    m_name = localName(name);
    return m_state = Token::EndElement;
}

bool XmlScanner::appendText(QString *out)
{
    if (m_state != Token::Text)
        return true;
    const QByteArrayView text = m_text;
    // XML 1.0 allows no control character but tab and the line ends, raw
    // or as a reference.
    for (const char c : text) {
        if ((unsigned char)c < 0x20 && c != '\t' && c != '\n' && c != '\r') {
            m_error = QStringLiteral("a control character (0x%1) in the text").arg(int(c), 2, 16, QLatin1Char('0'));
            m_state = Token::Error;
            return false;
        }
    }
    if (m_textIsCdata || !text.contains('&')) {
        if (out)
            *out += QString::fromUtf8(text);
        return true;
    }
    QString checked;
    if (!out)
        out = &checked;
    qsizetype from = 0;
    while (from < text.size()) {
        const qsizetype amp = text.indexOf('&', from);
        if (amp < 0) {
            *out += QString::fromUtf8(text.sliced(from));
            break;
        }
        *out += QString::fromUtf8(text.sliced(from, amp - from));
        const qsizetype semicolon = text.indexOf(';', amp);
        if (semicolon < 0 || semicolon - amp > 12) {
            m_error = QStringLiteral("a '&' that starts no reference");
            m_state = Token::Error;
            return false;
        }
        const QByteArrayView reference = text.sliced(amp + 1, semicolon - amp - 1);
        char32_t c = 0;
        if (reference == "lt")
            c = '<';
        else if (reference == "gt")
            c = '>';
        else if (reference == "amp")
            c = '&';
        else if (reference == "quot")
            c = '"';
        else if (reference == "apos")
            c = '\'';
        else if (reference.startsWith('#')) {
            bool ok = false;
            const uint value = reference.startsWith("#x") ? reference.sliced(2).toByteArray().toUInt(&ok, 16)
                                                          : reference.sliced(1).toByteArray().toUInt(&ok, 10);
            c = char32_t(value);
            if (!ok || !isXmlChar(c)) {
                m_error = QStringLiteral("a character reference &%1; to no character XML allows").arg(shown(reference));
                m_state = Token::Error;
                return false;
            }
        } else {
            refuseEntities(QStringLiteral("the XML refers to an entity '%1': refused, nothing read").arg(shown(reference)));
            return false;
        }
        *out += QString::fromUcs4(&c, 1);
        from = semicolon + 1;
    }
    return true;
}

} // namespace slew::sky
