// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The five forms an element-set file comes in, told apart by what the file
// holds (a download has no extension, and a file's name may say nothing):
// TLE/3LE, CelesTrak's CSV, CCSDS OMM XML, JSON and CCSDS OMM KVN. Each is
// read into the one ElementSet type by its own reader, and any of them can
// be written from what Slew holds.

#include "elementset.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>
#include <QStringList>

#include <optional>

namespace slew::sky {

enum class ElementSetForm { Tle, Csv, OmmXml, Json, OmmKvn };

// "TLE", "CSV", "OMM XML", "JSON", "OMM KVN": how messages name a form.
QString formName(ElementSetForm form);
// The form a --format names: tle, csv, xml, json or kvn (any case).
std::optional<ElementSetForm> formFromName(QStringView name);

// The form of a file's bytes: '<' starts XML, '[' or '{' JSON, a first line
// of "KEYWORD =" KVN, a first line of comma-separated OMM keywords CSV;
// anything else is read as TLE (whose reader names what it cannot read).
ElementSetForm recogniseForm(const QByteArray &bytes);

// The sets a file's bytes hold, in the form they are in.
struct ElementSetText {
    ElementSetForm form = ElementSetForm::Tle;
    ElementSetRead read;
};
ElementSetText readElementSets(const QByteArray &bytes);

// An element-set file a user named (--tle): only a regular file of at most
// kLargestElementFile, read without blocking on a device or a FIFO, in any
// of the five forms, its sets merged by catalogue number.
struct ElementSetFile {
    ElementSetForm form = ElementSetForm::Tle;
    QList<ElementSet> sets;
    QList<ElementSetRefusal> refusals;
    int duplicates = 0; // sets dropped for an older copy of the same satellite
    QString error;      // the file could not be read at all
};
ElementSetFile readElementSetFile(const QString &path);

// The sets in a form. A TLE cannot carry every set (a catalogue number
// above 339999): those are left out, and `left` names each and says why.
struct WrittenElementSets {
    QByteArray bytes;
    QStringList left;
};
WrittenElementSets writeElementSets(const QList<ElementSet> &sets, ElementSetForm form,
                                    const QDateTime &created = QDateTime::currentDateTimeUtc());

} // namespace slew::sky
