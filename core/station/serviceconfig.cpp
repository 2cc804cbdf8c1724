// SPDX-License-Identifier: GPL-3.0-or-later
#include "serviceconfig.h"

#include "input/finitenumber.h"

#include <QObject>

namespace slew::station {

std::optional<QList<int>> parseRotorList(const QString &text, QString *error)
{
    QList<int> rotors;
    auto add = [&](int n) {
        if (n < 1 || n > 4) {
            *error = QObject::tr("rotors are 1 to 4, not %1").arg(n);
            return false;
        }
        if (rotors.contains(n)) {
            *error = QObject::tr("rotor %1 is named twice").arg(n);
            return false;
        }
        rotors.append(n);
        return true;
    };
    for (const QString &item : text.split(u',')) {
        const QStringList range = item.trimmed().split(u'-');
        bool okFirst = false, okLast = false;
        const int first = range.front().trimmed().toInt(&okFirst);
        const int last = range.size() == 2 ? range.back().trimmed().toInt(&okLast) : first;
        if (range.size() > 2 || !okFirst || (range.size() == 2 && !okLast) || last < first) {
            *error = QObject::tr("'%1' is not a rotor or a range of rotors (as in 1,2,4 or 1-4)").arg(item.trimmed());
            return std::nullopt;
        }
        for (int n = first; n <= last; ++n) {
            if (!add(n))
                return std::nullopt;
        }
    }
    return rotors;
}

std::optional<model::RotatorLimits> parseLimits(const QString &text, QString *error)
{
    const QStringList axes = text.split(u',');
    auto range = [](const QString &part, double *low, double *high) {
        const QStringList ends = part.split(u':');
        if (ends.size() != 2)
            return false;
        const std::optional<double> a = input::finiteNumber(ends[0]), b = input::finiteNumber(ends[1]);
        if (!a || !b)
            return false;
        *low = *a;
        *high = *b;
        return true;
    };
    model::RotatorLimits limits;
    if (axes.size() != 2 || !range(axes[0], &limits.azMin, &limits.azMax) || !range(axes[1], &limits.elMin, &limits.elMax)) {
        *error = QObject::tr("expected AZMIN:AZMAX,ELMIN:ELMAX, as 0:450,0:180");
        return std::nullopt;
    }
    if (const QString why = limits.validate(); !why.isEmpty()) {
        *error = why;
        return std::nullopt;
    }
    return limits;
}

} // namespace slew::station
