// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/trackingline.h"

#include "sky/utctime.h"
#include "station/station.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <algorithm>
#include <cmath>

namespace slew::ui {

namespace {

QString utcClock(double julian)
{
    return sky::utcFromJulian(julian).toString(QStringLiteral("HH:mm:ss"));
}

} // namespace

TrackingLine::TrackingLine(std::function<Reading()> read, QWidget *parent) : QLabel(parent), m_read(std::move(read))
{
    setObjectName(QStringLiteral("trackingLine"));
    setTextFormat(Qt::PlainText);
    setWordWrap(true);
    setAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    connect(&m_tick, &QTimer::timeout, this, &TrackingLine::refresh);
    m_tick.start(1000);
    refresh();
}

TrackingLine::TrackingLine(station::Station *station, QWidget *parent)
    : TrackingLine(
          [station] {
              return Reading{station::trackingNow(station->passRunner()), station->clock()->nowJulian()};
          },
          parent)
{
    tracking::PassRunner *runner = station->passRunner();
    connect(&runner->tracker(), &tracking::Tracker::stateChanged, this, &TrackingLine::refresh);
    connect(runner, &tracking::PassRunner::logLine, this, &TrackingLine::refresh); // planned, started, stopped
    connect(station->clock(), &tracking::StationClock::changed, this, &TrackingLine::refresh);
}

QString TrackingLine::countdown(double seconds)
{
    // Whole seconds left, as a countdown shows them. A Julian day carries
    // times to some 40 µs: 427.9999 s of its arithmetic is 7:08.
    const qint64 s = qint64(std::floor(std::max(0.0, seconds) + 1e-3));
    return QStringLiteral("%1:%2:%3").arg(s / 3600).arg((s / 60) % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'));
}

QString TrackingLine::textFor(const station::TrackingNow &followed, double nowJulian)
{
    using Phase = station::TrackingNow::Phase;
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
    const Reading now = m_read();
    const QString text = textFor(now.followed, now.nowJulian);
    if (text != this->text()) // a label's new text lays its column out again
        setText(text);
    setEnabled(now.followed.phase != station::TrackingNow::Phase::Off); // greyed when there is nothing to say
}

} // namespace slew::ui
