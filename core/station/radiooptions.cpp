// SPDX-License-Identifier: GPL-3.0-or-later
#include "radiooptions.h"

#include "input/logtext.h"
#include "radio/transponderimport.h"
#include "radio/transponderset.h"

#include <QFileInfo>
#include <QObject>
#include <QRegularExpression>

namespace slew::station {

using radio::RadioPlan;
using radio::Transponder;

std::optional<radio::DopplerOn> parseDopplerOn(const QString &text, QString *error)
{
    const QString t = text.trimmed().toLower();
    if (t == u"both")
        return radio::DopplerOn::Both;
    if (t == u"downlink")
        return radio::DopplerOn::DownlinkOnly;
    if (t == u"uplink")
        return radio::DopplerOn::UplinkOnly;
    *error = QObject::tr("'%1': expected both, downlink or uplink").arg(input::loggableText(text, 24));
    return std::nullopt;
}

std::optional<radio::VfoLayout> parseVfoLayout(const QString &text, QString *error)
{
    const QString t = text.trimmed().toLower();
    if (t == u"split")
        return radio::VfoLayout::Split;
    if (t == u"main-sub")
        return radio::VfoLayout::MainSub;
    *error = QObject::tr("'%1': expected split or main-sub").arg(input::loggableText(text, 24));
    return std::nullopt;
}

std::optional<radio::UplinkFollowsDial> parseUplinkFollows(const QString &text, QString *error)
{
    const QString t = text.trimmed().toLower();
    if (t == u"no")
        return radio::UplinkFollowsDial::No;
    if (t == u"same")
        return radio::UplinkFollowsDial::SameWay;
    if (t == u"opposite")
        return radio::UplinkFollowsDial::OppositeWay;
    *error = QObject::tr("'%1': expected no, same or opposite").arg(input::loggableText(text, 24));
    return std::nullopt;
}

namespace {

// The satellite's transponders from every file, in the order given.
std::optional<radio::TransponderSet> readTransponders(const QStringList &files, int noradId, QStringList *notes,
                                                      QString *error)
{
    radio::TransponderSet set;
    for (const QString &path : files) {
        const bool trsp = QFileInfo(path).suffix().compare(QLatin1String("trsp"), Qt::CaseInsensitive) == 0;
        // A .trsp file not named after a satellite is taken as the tracked one's.
        const radio::TransponderImport read =
            trsp ? radio::readGpredictTrspFile(path, radio::noradIdFromTrspFileName(path) ? std::nullopt
                                                                                           : std::optional<int>(noradId))
                 : radio::readSatnogsTransmittersFile(path);
        if (!read.ok()) {
            *error = read.error;
            return std::nullopt;
        }
        *notes += read.skipReport();
        set.merge(read.transponders);
    }
    return set;
}

std::optional<Transponder> pick(const radio::TransponderSet &set, int noradId, const QString &name,
                                const QStringList &files, QString *error)
{
    const QList<Transponder> mine = set.forSatellite(noradId);
    if (name.isEmpty()) {
        if (const std::optional<Transponder> t = set.defaultFor(noradId))
            return t;
        *error = mine.isEmpty()
                     ? QObject::tr("%1 has no transponder for NORAD %2").arg(files.join(QLatin1String(", "))).arg(noradId)
                     : QObject::tr("NORAD %1 has no transponder that is alive; name one with --transponder").arg(noradId);
        return std::nullopt;
    }
    for (const Transponder &t : mine) {
        if (t.description.startsWith(name.trimmed(), Qt::CaseInsensitive))
            return t;
    }
    QStringList names;
    for (const Transponder &t : mine)
        names << QLatin1Char('\'') + input::loggableText(t.displayName(), 60) + QLatin1Char('\'');
    *error = QObject::tr("no transponder of NORAD %1 is named '%2'%3")
                 .arg(noradId)
                 .arg(input::loggableText(name, 60))
                 .arg(names.isEmpty() ? QString() : QObject::tr(" (it has %1)").arg(names.join(QLatin1String(", "))));
    return std::nullopt;
}

} // namespace

std::optional<RadioPlan> resolveRadioPlan(const RadioOptions &options, int noradId, QStringList *notes, QString *error)
{
    RadioPlan plan;
    if (!options.transponderFiles.isEmpty()) {
        const std::optional<radio::TransponderSet> set = readTransponders(options.transponderFiles, noradId, notes, error);
        if (!set)
            return std::nullopt;
        const std::optional<Transponder> t = pick(*set, noradId, options.transponderName, options.transponderFiles, error);
        if (!t)
            return std::nullopt;
        QString note;
        const std::optional<RadioPlan> made = radio::planFor(*t, &note, error);
        if (!made)
            return std::nullopt;
        plan = *made;
        if (!note.isEmpty())
            *notes << note;
    } else if (options.downlinkHz) {
        plan.frequencies.downlinkHz = *options.downlinkHz;
        plan.frequencies.uplinkHz = options.uplinkHz;
        plan.noradId = noradId;
    } else {
        *error = QObject::tr("the radio needs its frequencies: --downlink (and --uplink), or --transponders");
        return std::nullopt;
    }
    if (options.uplinkFollows)
        plan.frequencies.uplinkFollows = *options.uplinkFollows;
    plan.frequencies.correct = options.correct;
    plan.frequencies.downlinkOffsetHz = options.downlinkOffsetHz;
    plan.frequencies.uplinkOffsetHz = options.uplinkOffsetHz;
    if (!options.downlinkMode.isEmpty())
        plan.receiveMode = options.downlinkMode;
    if (!options.uplinkMode.isEmpty())
        plan.transmitMode = options.uplinkMode;
    if (plan.frequencies.correct == radio::DopplerOn::UplinkOnly && !plan.frequencies.uplinkHz) {
        *error = QObject::tr("Doppler on the uplink only, but there is no uplink");
        return std::nullopt;
    }
    return plan;
}

} // namespace slew::station
