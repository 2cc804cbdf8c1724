// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotor/positionreadout.h"

#include "face/stationface.h"
#include "sky/utctime.h"

#include <QGridLayout>
#include <QLabel>

#include <cmath>

namespace slew::ui {

// A figure as shown to a tenth: -0.04 rounds to "-0.0" in printf, which
// reads as a sign error; it is shown as 0.0.
double shownTenths(double value)
{
    const double rounded = std::round(value * 10.0) / 10.0;
    return rounded == 0.0 ? 0.0 : rounded;
}

namespace {

const QString kNoFigure = QStringLiteral("---.-°");

QLabel *bigFigure(const QString &name)
{
    auto *l = new QLabel(kNoFigure);
    l->setObjectName(name);
    QFont f(QStringLiteral("monospace"));
    f.setStyleHint(QFont::Monospace);
    f.setPointSize(22);
    f.setBold(true);
    l->setFont(f);
    l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return l;
}

QLabel *line(const QString &name)
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

PositionReadout::PositionReadout(face::StationFace *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("positionReadout"));
    m_az = bigFigure(QStringLiteral("readoutAzimuth"));
    m_el = bigFigure(QStringLiteral("readoutElevation"));
    m_target = line(QStringLiteral("readoutTarget"));
    m_target->setWordWrap(false);
    m_status = line(QStringLiteral("readoutStatus"));

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("Azimuth")), 0, 0);
    grid->addWidget(m_az, 0, 1);
    grid->addWidget(new QLabel(tr("Elevation")), 1, 0);
    grid->addWidget(m_el, 1, 1);
    grid->addWidget(m_target, 2, 0, 1, 2);
    grid->addWidget(m_status, 3, 0, 1, 2);
    if (!station->isLocal()) {
        // The local window has the connection bar and the Tracking tab.
        m_link = line(QStringLiteral("readoutLink"));
        m_link->setText(tr("Waiting for the station's state"));
        m_pass = line(QStringLiteral("readoutPass"));
        grid->addWidget(m_link, 4, 0, 1, 2);
        grid->addWidget(m_pass, 5, 0, 1, 2);
    }

    connect(station, &face::StationFace::stateChanged, this, &PositionReadout::showState);
    // From afar, the telemetry carries the position at the poll rate; the
    // state, while the antenna only moves, once a second.
    connect(station, &face::StationFace::telemetryReceived, this, &PositionReadout::showSample);
    // Greyed: the figures are the last ones known.
    connect(station, &face::StationFace::liveChanged, this, &QWidget::setEnabled);
    setEnabled(station->isLive());
    if (const std::optional<face::StationState> state = station->state())
        showState(*state);
}

QString PositionReadout::passText(const face::StationState &s)
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

void PositionReadout::showState(const face::StationState &s)
{
    m_stale = s.stale;
    if (s.position && s.link != u"connecting")
        showPosition(s.position->x(), s.position->y(), s.stale);
    else
        clearPosition();
    m_target->setText(s.target && s.link != u"connecting"
                          ? tr("Target  %1°  %2°").arg(shownTenths(s.target->x()), 0, 'f', 1).arg(shownTenths(s.target->y()), 0, 'f', 1)
                          : QString());
    if (!s.azimuthStatus)
        m_status->clear();
    else if (!s.elevationStatus)
        m_status->setText(tr("Status: %1").arg(*s.azimuthStatus));
    else
        m_status->setText(tr("Az: %1   El: %2").arg(*s.azimuthStatus, *s.elevationStatus));
    if (m_link) {
        QString link = tr("Rotator link: %1").arg(s.link);
        if (!s.linkDetail.isEmpty())
            link += tr(" (%1)").arg(s.linkDetail);
        if (!s.controllerVersion.isEmpty())
            link += tr(" · %1").arg(s.controllerVersion);
        if (s.operatorHold)
            link += tr(" · the operator at the station holds remote control");
        m_link->setText(link);
        m_pass->setText(passText(s));
    }
}

void PositionReadout::showSample(const face::TelemetrySample &sample)
{
    if (sample.az && sample.el)
        showPosition(*sample.az, *sample.el, m_stale);
}

void PositionReadout::showPosition(double az, double el, bool stale)
{
    m_az->setText(QStringLiteral("%1°").arg(shownTenths(az), 6, 'f', 1));
    m_el->setText(QStringLiteral("%1°").arg(shownTenths(el), 6, 'f', 1));
    const QString style = stale ? QStringLiteral("color:#808080;") : QStringLiteral("color:#4cd964;");
    m_az->setStyleSheet(style);
    m_el->setStyleSheet(style);
    m_az->setToolTip(stale ? tr("No fresh position from the controller") : QString());
}

void PositionReadout::clearPosition()
{
    m_az->setText(kNoFigure);
    m_el->setText(kNoFigure);
}

} // namespace slew::ui
