// SPDX-License-Identifier: GPL-3.0-or-later
#include "trackoptions.h"

#include "elementsetoption.h"
#include "optionnames.h"

#include "sky/elementset.h"

#include <QCommandLineParser>

namespace slew::cli {

using tracking::TrackTarget;

namespace {

// A satellite by its catalogue number, anything else by its name.
QString identity(const TrackTarget &t)
{
    return t.kind == TrackTarget::Kind::Satellite ? QString::number(t.elements.catalogueNumber) : t.name();
}

} // namespace

std::optional<QList<TrackTarget>> readTrackTargets(const QCommandLineParser &parser, const OptionLabel &label,
                                                   QString *error)
{
    std::optional<ElementSetOption> sets; // read at the first satellite, once
    QList<TrackTarget> targets;
    for (const QString &given : parser.values(opt::track)) {
        const QString what = given.trimmed();
        TrackTarget target;
        QString badFixed;
        if (const auto fixed = TrackTarget::parseFixedOrCelestial(what, &badFixed)) {
            target = *fixed;
        } else if (!badFixed.isEmpty()) {
            *error = QStringLiteral("%1 %2").arg(label(opt::track), badFixed);
            return std::nullopt;
        } else if (what.compare(QLatin1String("sun"), Qt::CaseInsensitive) == 0) {
            target.kind = TrackTarget::Kind::Sun;
        } else if (what.compare(QLatin1String("moon"), Qt::CaseInsensitive) == 0) {
            target.kind = TrackTarget::Kind::Moon;
        } else {
            if (!sets) {
                QString why;
                sets = readElementSetOption(parser, label, &why);
                if (!sets) {
                    *error = QStringLiteral("%1 %2: %3").arg(label(opt::track), shownValue(what), why);
                    return std::nullopt;
                }
            }
            QString why;
            const sky::ElementSet *found = sky::findOneSatellite(sets->sets, what, &why);
            if (!found) {
                // The sets that could not be read may be the one meant: say
                // why they were skipped, as --passes does.
                *error = QStringLiteral("%1: %2 in %3").arg(label(opt::track), why, sets->origin);
                for (const QString &skipped : sets->skipped.mid(0, 5))
                    *error += QStringLiteral("\n  ") + skipped;
                if (sets->skipped.size() > 5)
                    *error += QStringLiteral("\n  … and %1 more sets skipped").arg(sets->skipped.size() - 5);
                return std::nullopt;
            }
            target.elements = *found;
        }
        for (const TrackTarget &earlier : std::as_const(targets)) {
            if (earlier.kind == target.kind && identity(earlier) == identity(target)) {
                *error = QStringLiteral("%1 %2: %3 is given twice; a schedule takes each target once")
                             .arg(label(opt::track), shownValue(what), target.name());
                return std::nullopt;
            }
        }
        targets.append(target);
    }
    return targets;
}

bool readHorizonOption(const QCommandLineParser &parser, const OptionLabel &label,
                       std::shared_ptr<const sky::HorizonMask> *mask, QString *error)
{
    mask->reset();
    if (!parser.isSet(opt::horizon))
        return true;
    const sky::HorizonFile read = sky::readHorizonFile(parser.value(opt::horizon));
    if (!read.mask) {
        *error = QStringLiteral("%1: %2").arg(label(opt::horizon), read.error);
        return false;
    }
    *mask = read.mask;
    return true;
}

} // namespace slew::cli
