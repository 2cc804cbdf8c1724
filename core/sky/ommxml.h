// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// CCSDS OMM in XML (the NDM/XML schema): one <omm> element, or an <ndm>
// holding many, each with the OMM keywords as the tags of its metadata,
// meanElements and tleParameters. Only the keywords are read, wherever
// they sit inside their <omm>.
//
// XML from outside is read defensively: a document type declaration is
// refused at once, so no entity is ever declared, let alone expanded (the
// "billion laughs" and external-entity attacks need one); elements nested
// deeper than an OMM ever needs are refused; the file itself is capped
// before it gets here (kLargestElementFile). The XML itself is read by
// XmlScanner (xmlscanner.h).

#include "elementset.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>

namespace slew::sky {

// Deeper than any OMM (ndm, omm, body, segment, data, tleParameters, and a
// field: seven), with room for a wrapper or two.
inline constexpr int kDeepestOmmXml = 16;

ElementSetRead readOmmXml(const QByteArray &bytes);

// An <ndm> with one <omm> a set, created at `created` by "Slew".
QByteArray ommXmlText(const QList<ElementSet> &sets, const QDateTime &created);

} // namespace slew::sky
