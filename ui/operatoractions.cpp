// SPDX-License-Identifier: GPL-3.0-or-later
#include "operatoractions.h"

#include "rotor/positionreadout.h"

namespace slew::ui {

using Outcome = session::MoveWatch::Outcome;

QString describePosition(QPointF azEl)
{
    return QObject::tr("az %1°, el %2°")
        .arg(shownTenths(azEl.x()), 0, 'f', 1)
        .arg(shownTenths(azEl.y()), 0, 'f', 1);
}

OperatorActions::OperatorActions(session::MoveWatch *watch, QObject *parent) : QObject(parent), m_watch(watch)
{
    connect(watch, &session::MoveWatch::ended, this, &OperatorActions::onEnded);
}

void OperatorActions::moveStarted(const QString &what, std::optional<QPointF> target)
{
    m_what = what;
    action(what);
    m_watch->watch(target);
}

void OperatorActions::action(const QString &text)
{
    emit logged(station::AlarmMonitor::Severity::Info, text);
}

void OperatorActions::outcome(const QString &text, bool problem)
{
    emit logged(problem ? station::AlarmMonitor::Severity::Warning : station::AlarmMonitor::Severity::Info, text);
}

void OperatorActions::onEnded(Outcome result, QPointF at, double offDeg)
{
    const QString where = describePosition(at);
    switch (result) {
    case Outcome::Arrived:
        outcome(tr("%1: arrived, at %2").arg(m_what, where), false);
        break;
    case Outcome::StoppedShort:
        outcome(tr("%1: came to rest %2° from the target, at %3").arg(m_what).arg(offDeg, 0, 'f', 1).arg(where),
                true);
        break;
    case Outcome::Stopped:
        outcome(tr("%1: stopped at %2, %3° from the target").arg(m_what, where).arg(offDeg, 0, 'f', 1), false);
        break;
    case Outcome::Replaced:
        outcome(tr("%1: not finished, another target was sent").arg(m_what), false);
        break;
    case Outcome::Refused:
        outcome(tr("%1: not done, %2").arg(m_what, m_watch->refusal()), true);
        break;
    case Outcome::LinkLost:
        outcome(tr("%1: not finished, the link went down").arg(m_what), true);
        break;
    }
    emit moveEnded();
}

} // namespace slew::ui
