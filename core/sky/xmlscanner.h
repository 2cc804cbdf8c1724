// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A small, strict reader of the XML that element sets come in (CCSDS OMM,
// NDM/XML): elements, attributes, text, CDATA, comments and processing
// instructions of a UTF-8 document, checked for well-formedness as it goes
// (one root, every element closed by its own end tag, nothing but
// comments and whitespace around the root). What such a file never needs
// is refused, not read: a document type declaration (so no entity is ever
// declared or expanded, and nothing outside the file is ever fetched), a
// reference to any entity but XML's five predefined ones, another encoding
// than UTF-8, nesting deeper than the caller allows.
//
// It exists for speed: Qt's QXmlStreamReader takes some 300 ms of CPU for
// a 12,000-object catalogue in OMM XML, this about a tenth of that, which
// keeps every form of the active catalogue under 100 ms (README). Pure
// code on a byte array that must outlive the scanner; no allocation but
// the text asked for.

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <optional>
#include <vector>

namespace slew::sky {

class XmlScanner {
public:
    enum class Token { StartElement, EndElement, Text, End, Error };

    XmlScanner(QByteArrayView bytes, int deepest);

    // The next token. After End or Error it stays there.
    Token next();

    // A start or end element's local name (after any "prefix:").
    QByteArrayView name() const { return m_name; }
    // Appends the current Text token's characters to `out`, references
    // replaced; false, and error() set, for a reference it refuses. With no
    // `out`, the references are only checked.
    bool appendText(QString *out);
    // The line the current token starts on, 1-based.
    int line() const { return m_tokenLine; }
    // Why it stopped at Error.
    QString error() const { return m_error; }
    // Whether that was a declaration or a reference to an entity: the XML
    // tried to define or use what a hostile file uses, so nothing read from
    // it before should be trusted either.
    bool refusedEntities() const { return m_refusedEntities; }

private:
    Token fail(const QString &why);
    Token refuseEntities(const QString &why);
    Token startTag();
    Token endTag();
    std::optional<Token> markup(); // <! … and <? …: nothing for a comment or an instruction
    bool skipPast(QByteArrayView end);
    void countLines(qsizetype from, qsizetype to);
    bool readName(QByteArrayView *name);
    void skipSpace();
    bool atRootLevel() const { return m_open.empty(); }

    QByteArrayView m_bytes;
    qsizetype m_at = 0;
    int m_line = 1;
    int m_tokenLine = 1;
    int m_deepest;
    std::vector<QByteArrayView> m_open; // the names of the elements open now
    bool m_rootSeen = false;
    bool m_pendingEnd = false;          // an empty element's end, given next
    bool m_textIsCdata = false;
    QByteArrayView m_name;
    QByteArrayView m_text;
    QString m_error;
    bool m_refusedEntities = false;
    Token m_state = Token::Text;
};

} // namespace slew::sky
