// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/trackingline.h"

#include "face/stationface.h"
#include "sky/utctime.h"

#include <algorithm>
#include <cmath>

namespace slew::ui {

namespace {

QString utcClock(double julian)
{
    return sky::utcFromJulian(julian).toString(QStringLiteral("HH:mm:ss"));
}

} // namespace

TrackingLine::TrackingLine(face::StationFace *station, QWidget *parent) : QLabel(parent), m_station(station)
{
    setObjectName(QStringLiteral("trackingLine"));
    setTextFormat(Qt::PlainText);
    setWordWrap(true);
    setAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    connect(&m_tick, &QTimer::timeout, this, &TrackingLine::refresh);
    connect(station, &face::StationFace::stateChanged, this, &TrackingLine::refresh);
    m_tick.start(1000);
    refresh();
}

QString TrackingLine::countdown(double seconds)
{
    // Whole seconds left, as a countdown shows them. A Julian day carries
    // times to some 40 µs: 427.9999 s of its arithmetic is 7:08.
    const qint64 s = qint64(std::floor(std::max(0.0, seconds) + 1e-3));
    return QStringLiteral("%1:%2:%3").arg(s / 3600).arg((s / 60) % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'));
}

QString TrackingLine::textFor(const face::TrackingNow &followed, double nowJulian)
{
    using Phase = face::TrackingNow::Phase;
    const QString &name = followed.target;
    const auto secondsTo = [nowJulian](double julian) { return (julian - nowJulian) * sky::kSecondsPerDay; };
    switch (followed.phase) {
    case Phase::Off:
        return tr("Not tracking");
    case Phase::Planning:
        return tr("%1: finding the next pass").arg(name);
    case Phase::Done:
        return tr("%1: pass ended, finding the next").arg(name);
    case Phase::Waiting:
        if (!followed.pass)
            return tr("%1: the antenna is on its way").arg(name);
        if (followed.pass->aos.julian > nowJulian)
            return tr("Next: %1, AOS %2 UTC, in %3")
                .arg(name, utcClock(followed.pass->aos.julian), countdown(secondsTo(followed.pass->aos.julian)));
        return tr("%1: the antenna is on its way, LOS %2 UTC").arg(name, utcClock(followed.pass->los.julian));
    case Phase::Tracking:
        if (!followed.pass)
            return tr("Tracking %1").arg(name); // a fixed direction, the sun all day: no LOS to count to
        return tr("Tracking %1 until %2 UTC, %3 left")
            .arg(name, utcClock(followed.pass->los.julian), countdown(secondsTo(followed.pass->los.julian)));
    }
    return {};
}

void TrackingLine::refresh()
{
    const std::optional<face::StationState> state = m_station->state();
    const std::optional<qint64> nowMs = m_station->stationClockMs();
    const face::TrackingNow followed = state ? face::trackingOf(*state) : face::TrackingNow{};
    const QString text = textFor(followed, nowMs ? face::julianOfUnixMs(*nowMs) : 0.0);
    if (text != this->text()) // a label's new text lays its column out again
        setText(text);
    setEnabled(followed.phase != face::TrackingNow::Phase::Off); // greyed when there is nothing to say
}

} // namespace slew::ui
