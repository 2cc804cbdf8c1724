// SPDX-License-Identifier: GPL-3.0-or-later
#include "timecontroller.h"

#include "rehearsalmarker.h"

#include "sky/skyvector.h"
#include "station/station.h"
#include "tracking/simulatorpace.h"
#include "sky/utctime.h"

#include <QDateTimeEdit>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QTimeZone>
#include <QVBoxLayout>

#include <cmath>

namespace slew::ui {

namespace {

double julianOf(const QDateTime &utc)
{
    return sky::julianFromUnixSeconds(double(utc.toMSecsSinceEpoch()) / 1000.0);
}

} // namespace

TimeController::TimeController(station::Station *station, QWidget *parent)
    : QDialog(parent), m_clock(station->clock()), m_pace(station->simulatorPace())
{
    setObjectName(QStringLiteral("timeController"));
    setWindowTitle(tr("Time controller"));

    m_start = new QDateTimeEdit;
    m_start->setObjectName(QStringLiteral("timeStart"));
    // UTC as each Qt says it: setTimeZone came with 6.7, and 6.8 deprecates
    // setTimeSpec.
#if QT_VERSION >= QT_VERSION_CHECK(6, 7, 0)
    m_start->setTimeZone(QTimeZone::UTC);
#else
    m_start->setTimeSpec(Qt::UTC);
#endif
    m_start->setDisplayFormat(QStringLiteral("yyyy-MM-dd HH:mm:ss"));
    m_start->setCalendarPopup(true);
    // The next whole minute: a time an operator would type.
    const QDateTime now = QDateTime::currentDateTimeUtc();
    m_start->setDateTime(now.addSecs(60 - now.time().second()).addMSecs(-now.time().msec()));
    m_rate = new QSpinBox;
    m_rate->setObjectName(QStringLiteral("timeRate"));
    m_rate->setRange(1, int(tracking::StationClock::kMaxRate));
    m_rate->setSuffix(QStringLiteral(" ×"));
    m_rate->setToolTip(tr("How many times faster than real time the station clock runs. "
                          "While rehearsing, a new rate applies at once, from the time the clock reads."));
    m_startButton = new QPushButton(tr("Start here"));
    m_startButton->setObjectName(QStringLiteral("startRehearsal"));
    m_startButton->setToolTip(tr("Start the station clock at this UTC time and rate: a rehearsal."));
    m_realTimeButton = new QPushButton(tr("Real time"));
    m_realTimeButton->setObjectName(QStringLiteral("realTime"));
    m_realTimeButton->setToolTip(tr("The station clock follows the system's UTC again."));
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("timeControllerState"));
    m_state->setWordWrap(true);
    // Room for the longest state line, so the dialog does not resize as it changes.
    m_state->setMinimumWidth(fontMetrics().averageCharWidth() * 48);

    auto *startRow = new QHBoxLayout;
    startRow->addWidget(m_start, 1);
    startRow->addWidget(new QLabel(tr("UTC")));
    auto *form = new QFormLayout;
    form->addRow(tr("Start at"), startRow);
    form->addRow(tr("Rate"), m_rate);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_startButton);
    buttons->addWidget(m_realTimeButton);
    buttons->addStretch(1);
    auto *close = new QDialogButtonBox(QDialogButtonBox::Close);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(buttons);
    layout->addWidget(m_state);
    layout->addWidget(close);

    connect(m_startButton, &QPushButton::clicked, this,
            [this] { rehearse(julianOf(m_start->dateTime()), double(m_rate->value())); });
    connect(m_realTimeButton, &QPushButton::clicked, this, &TimeController::followRealTime);
    connect(m_rate, &QSpinBox::valueChanged, this, &TimeController::onRateChosen);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::hide);
    connect(m_clock, &tracking::StationClock::changed, this, &TimeController::showState);
    connect(m_pace, &tracking::SimulatorPace::followsChanged, this, &TimeController::showState);
    connect(&m_tick, &QTimer::timeout, this, &TimeController::showState);
    m_tick.start(1000);
    showState();
}

void TimeController::rehearse(double startJulian, double rate)
{
    m_start->setDateTime(sky::utcFromJulian(startJulian));
    {
        // The field shows the rate; the clock takes it once, below.
        const QSignalBlocker quiet(m_rate);
        m_rate->setValue(int(std::lround(rate)));
    }
    m_clock->rehearse(startJulian, rate);
}

void TimeController::followRealTime()
{
    m_clock->followRealTime();
}

void TimeController::showController()
{
    show(); // non-modal: the window keeps working
    raise();
    activateWindow();
}

void TimeController::onRateChosen(int rate)
{
    // While rehearsing the clock goes on at the new rate from where it is;
    // in real time the rate waits for Start here.
    m_clock->setRate(double(rate));
}

void TimeController::showState()
{
    m_realTimeButton->setEnabled(m_clock->isRehearsal());
    if (!m_clock->isRehearsal()) {
        m_state->setText(tr("Real time: the station clock is the system's UTC."));
        return;
    }
    QString text = tr("Rehearsal: the station clock reads %1 and runs %2.")
                       .arg(RehearsalMarker::clockText(m_clock->nowJulian()), RehearsalMarker::rateText(m_clock->rate()));
    if (m_pace->follows())
        text += u' ' + tr("The simulator runs at the same rate.");
    else if (m_clock->rate() > 1.0)
        text += u' ' + tr("The rotator keeps its own pace: only the built-in simulator runs faster with the clock.");
    m_state->setText(text);
}

} // namespace slew::ui
