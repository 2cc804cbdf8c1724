// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remotereadout.h"

#include "sky/utctime.h"

#include <QDateTime>
#include <QGridLayout>
#include <QLabel>

namespace slew::ui {
namespace {

QLabel *plainLabel(const QString &name)
{
    auto *l = new QLabel;
    l->setObjectName(name);
    l->setTextFormat(Qt::PlainText);
    l->setWordWrap(true);
    return l;
}

QString utcTime(qint64 ms)
{
    return sky::utcFromUnixMs(ms).toString(QStringLiteral("HH:mm:ss"));
}

} // namespace

RemoteReadout::RemoteReadout(QWidget *parent) : QWidget(parent)
{
    m_az = plainLabel(QStringLiteral("remoteAzimuth"));
    m_el = plainLabel(QStringLiteral("remoteElevation"));
    for (QLabel *big : {m_az, m_el}) {
        // "Az 359.9°" never needs a second line; a wrapping label's height
        // follows its width, and a layout may then give it less than its
        // big font needs (seen once, 21 px of 28, on a loaded machine).
        big->setWordWrap(false);
        QFont f = big->font();
        f.setPointSizeF(f.pointSizeF() * 2.0);
        f.setBold(true);
        big->setFont(f);
    }
    m_target = plainLabel(QStringLiteral("remoteTarget"));
    m_link = plainLabel(QStringLiteral("remoteLink"));
    m_tracking = plainLabel(QStringLiteral("remoteTracking"));
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(m_az, 0, 0);
    grid->addWidget(m_el, 0, 1);
    grid->addWidget(m_target, 1, 0, 1, 2);
    grid->addWidget(m_link, 2, 0, 1, 2);
    grid->addWidget(m_tracking, 3, 0, 1, 2);
    m_az->setText(tr("Az —"));
    m_el->setText(tr("El —"));
    m_link->setText(tr("Waiting for the station's state"));
}

QString RemoteReadout::trackingText(const face::StationState &s)
{
    // What tracking does now is the line beside STOP (trackingline.h);
    // here, the pass it is about.
    if (s.tracking == u"off" || !s.passAosMs || !s.passLosMs)
        return {};
    const QString target = s.trackingNorad ? tr("%1 (NORAD %2)").arg(s.trackingTarget).arg(*s.trackingNorad)
                                           : s.trackingTarget;
    QString text = tr("Pass of %1: %2–%3 UTC").arg(target, utcTime(*s.passAosMs), utcTime(*s.passLosMs));
    if (s.passMaxElevation)
        text += tr(", highest %1°").arg(*s.passMaxElevation, 0, 'f', 1);
    return text;
}

void RemoteReadout::showPosition(double az, double el)
{
    m_az->setText(tr("Az %1°").arg(az, 0, 'f', 1));
    m_el->setText(m_azimuthOnly ? QString() : tr("El %1°").arg(el, 0, 'f', 1));
}

void RemoteReadout::showState(const face::StationState &s)
{
    m_azimuthOnly = s.azimuthOnly;
    if (s.position) {
        showPosition(s.position->x(), s.position->y());
    } else {
        m_az->setText(tr("Az —"));
        m_el->setText(tr("El —"));
    }
    QString target = s.target ? tr("Target az %1°, el %2°").arg(s.target->x(), 0, 'f', 1).arg(s.target->y(), 0, 'f', 1)
                              : tr("No target");
    target += s.moving ? tr(" · moving") : tr(" · at rest");
    if (s.stale)
        target += tr(" · position stale");
    m_target->setText(target);
    QString link = tr("Rotator link: %1").arg(s.link);
    if (!s.linkDetail.isEmpty())
        link += tr(" (%1)").arg(s.linkDetail);
    if (!s.controllerVersion.isEmpty())
        link += tr(" · %1").arg(s.controllerVersion);
    if (s.operatorHold)
        link += tr(" · the operator at the station holds remote control");
    m_link->setText(link);
    m_tracking->setText(trackingText(s));
}

void RemoteReadout::setLive(bool live)
{
    setEnabled(live); // greyed: the figures are the last ones known
}

} // namespace slew::ui
