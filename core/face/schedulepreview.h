// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a station would make of a schedule before it runs one: each target
// as it found it (or why it found none), and the plan of the hours asked,
// every pass taken or dropped with the reason. Made by the station's own
// element sets, place, horizon and rotator, so a preview shown far away is
// the plan the station would follow. Carried over MQTT in the reply to a
// `schedule_preview` command (remote/remotecommand.h).

#include "schedule/schedule.h"

#include <QList>
#include <QMetaType>
#include <QString>

namespace slew::face {

// A target named in words, as the station read it.
struct NamedTarget {
    QString asked;   // as the operator wrote it
    QString name;    // the target's own name ("FOX-1B (AO-91)", "Sun"); empty when none was found
    int norad = 0;   // a satellite's catalogue number; 0 for any other target
    QString problem; // why none was found, in the operator's words; empty when found

    bool isFound() const { return problem.isEmpty(); }
    // How to name it again so the station finds this one and no other:
    // a satellite by its catalogue number, any other target as asked.
    QString spec() const { return norad > 0 ? QString::number(norad) : asked; }
};

struct SchedulePreview {
    QList<NamedTarget> targets;  // one for each asked, in the order asked
    schedule::Schedule schedule; // planned from the targets found
    // Why no plan was made (the station has no place yet), in the
    // operator's words; the targets are named all the same.
    QString notPlanned;
};

} // namespace slew::face

Q_DECLARE_METATYPE(slew::face::SchedulePreview)
