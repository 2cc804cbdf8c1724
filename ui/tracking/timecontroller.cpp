// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/timecontroller.h"

#include "tracking/rehearsalmarker.h"
#include "widgets/utctimefield.h"

#include "sky/skyvector.h"
#include "sky/utctime.h"
#include "station/station.h"
#include "tracking/simulatorpace.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace slew::ui {

namespace {

constexpr double kMinutesPerDay = 24.0 * 60.0;

// "+2:05" from the slider's start.
QString hoursAndMinutes(int minutes)
{
    return QStringLiteral("+%1:%2").arg(minutes / 60).arg(minutes % 60, 2, 10, QLatin1Char('0'));
}

} // namespace

TimeController::TimeController(station::Station *station, QWidget *parent)
    : QDialog(parent), m_clock(station->clock()), m_pace(station->simulatorPace())
{
    setObjectName(QStringLiteral("timeController"));
    setWindowTitle(tr("Time controller"));

    m_start = new UtcTimeField;
    m_start->setObjectName(QStringLiteral("timeStart"));
    // The next whole minute: a time an operator would type.
    m_start->setJulian(std::ceil(sky::julianNow() * kMinutesPerDay) / kMinutesPerDay);
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
    m_pauseButton = new QPushButton(tr("Pause"));
    m_pauseButton->setObjectName(QStringLiteral("pauseClock"));
    m_pauseButton->setToolTip(tr("Hold the station clock at the instant it reads (in real time, that starts a "
                                 "rehearsal); Resume runs it on from there."));
    m_step = new QSpinBox;
    m_step->setObjectName(QStringLiteral("stepSeconds"));
    m_step->setRange(1, 3600);
    m_step->setValue(10);
    m_step->setSuffix(QStringLiteral(" s"));
    m_step->setToolTip(tr("How far Step moves the paused station clock forward."));
    m_stepButton = new QPushButton(tr("Step"));
    m_stepButton->setObjectName(QStringLiteral("stepClock"));
    m_stepButton->setToolTip(tr("Move the paused station clock forward by the step: a tracker follows to that instant."));
    m_slider = new QSlider(Qt::Horizontal);
    m_slider->setObjectName(QStringLiteral("timeSlider"));
    m_slider->setRange(0, kSliderMinutes);
    m_slider->setSingleStep(1);
    m_slider->setPageStep(30);
    // One jump where the handle is let go, not one for every minute it passes.
    m_slider->setTracking(false);
    m_slider->setToolTip(tr("The next %1 hours from where the rehearsal started: let go to put the station clock "
                            "there (paused, it stays paused).")
                             .arg(kSliderMinutes / 60));
    m_sliderLine = new QLabel;
    m_sliderLine->setObjectName(QStringLiteral("timeSliderLine"));
    m_sliderLine->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("+12:00 2026-12-05 15:24 UTC  ")));
    m_problem = new QLabel;
    m_problem->setObjectName(QStringLiteral("timeControllerProblem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color:#c62828;"));
    m_problem->hide();
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("timeControllerState"));
    m_state->setWordWrap(true);
    // Room for the longest state line, so the dialog does not resize as it changes.
    m_state->setMinimumWidth(fontMetrics().averageCharWidth() * 48);

    auto *startRow = new QHBoxLayout;
    startRow->addWidget(m_start, 1);
    startRow->addWidget(new QLabel(tr("UTC")));
    auto *sliderRow = new QHBoxLayout;
    sliderRow->addWidget(m_slider, 1);
    sliderRow->addWidget(m_sliderLine);
    auto *form = new QFormLayout;
    form->addRow(tr("Start at"), startRow);
    form->addRow(tr("Rate"), m_rate);
    form->addRow(tr("Move to"), sliderRow);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_startButton);
    buttons->addWidget(m_realTimeButton);
    buttons->addSpacing(12);
    buttons->addWidget(m_pauseButton);
    buttons->addWidget(m_stepButton);
    buttons->addWidget(m_step);
    buttons->addStretch(1);
    auto *close = new QDialogButtonBox(QDialogButtonBox::Close);
    // Enter in a field does not press a button: in the step or rate field it
    // would otherwise press the next one along (Start here, a jump back).
    // Enter in the start field starts there (returnPressed, below).
    for (QPushButton *b : {m_startButton, m_realTimeButton, m_pauseButton, m_stepButton,
                           close->button(QDialogButtonBox::Close)})
        b->setAutoDefault(false);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addLayout(buttons);
    layout->addWidget(m_state);
    layout->addWidget(close);

    connect(m_startButton, &QPushButton::clicked, this, &TimeController::startAsTyped);
    connect(m_start, &QLineEdit::returnPressed, this, &TimeController::startAsTyped);
    connect(m_start, &QLineEdit::textEdited, m_problem, &QLabel::hide);
    connect(m_realTimeButton, &QPushButton::clicked, this, &TimeController::followRealTime);
    connect(m_rate, &QSpinBox::valueChanged, this, &TimeController::onRateChosen);
    connect(m_pauseButton, &QPushButton::clicked, this, &TimeController::togglePause);
    connect(m_stepButton, &QPushButton::clicked, this, [this] { m_clock->step(double(m_step->value())); });
    connect(m_slider, &QSlider::valueChanged, this, &TimeController::onSliderMoved);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::hide);
    for (auto signal : {&tracking::StationClock::changed, &tracking::StationClock::stepped})
        connect(m_clock, signal, this, &TimeController::showState);
    connect(m_clock, &tracking::StationClock::pausedChanged, this, &TimeController::showState);
    connect(m_pace, &tracking::SimulatorPace::followsChanged, this, &TimeController::showState);
    connect(&m_tick, &QTimer::timeout, this, &TimeController::showState);
    m_tick.start(1000);
    showState();
}

void TimeController::rehearse(double startJulian, double rate)
{
    m_start->setJulian(startJulian);
    m_problem->hide();
    {
        // The field shows the rate; the clock takes it once, below.
        const QSignalBlocker quiet(m_rate);
        m_rate->setValue(int(std::lround(rate)));
    }
    m_origin = startJulian;
    m_clock->rehearse(startJulian, rate);
}

void TimeController::rehearsePass(double aosJulian)
{
    rehearse(aosJulian - kPassLeadSeconds / sky::kSecondsPerDay, double(m_rate->value()));
}

void TimeController::followRealTime()
{
    m_origin.reset();
    m_clock->followRealTime();
}

void TimeController::showController()
{
    show(); // non-modal: the window keeps working
    raise();
    activateWindow();
}

void TimeController::startAsTyped()
{
    QString why;
    const std::optional<double> start = m_start->julian(&why);
    if (!start) {
        // The clock stays as it is; the field keeps what was typed, to correct.
        m_problem->setText(tr("Start at: %1. The station clock is unchanged.").arg(why));
        m_problem->show();
        return;
    }
    rehearse(*start, double(m_rate->value()));
}

void TimeController::onRateChosen(int rate)
{
    // While rehearsing the clock goes on at the new rate from where it is;
    // in real time the rate waits for Start here.
    m_clock->setRate(double(rate));
}

void TimeController::togglePause()
{
    if (m_clock->isPaused()) {
        m_clock->resume();
        return;
    }
    if (!m_clock->isRehearsal())
        m_origin = m_clock->nowJulian(); // the rehearsal a pause starts begins here
    m_clock->pause();
}

double TimeController::sliderOrigin() const
{
    // In real time the slider starts at the current minute.
    return m_origin.value_or(std::floor(m_clock->nowJulian() * kMinutesPerDay) / kMinutesPerDay);
}

void TimeController::onSliderMoved(int minutes)
{
    const double origin = sliderOrigin();
    m_origin = origin;
    // A jump: whoever planned by the clock plans again. A paused clock
    // stays paused at the new instant, exactly: started and paused again,
    // it ran on while the planners answered the start.
    const double to = origin + minutes / kMinutesPerDay;
    if (m_clock->isPaused())
        m_clock->holdAt(to);
    else
        m_clock->rehearse(to, double(m_rate->value()));
}

void TimeController::showState()
{
    const bool rehearsal = m_clock->isRehearsal(), paused = m_clock->isPaused();
    m_realTimeButton->setEnabled(rehearsal);
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
    m_stepButton->setEnabled(paused);
    m_step->setEnabled(paused);
    showSlider();
    if (!rehearsal) {
        m_state->setText(tr("Real time: the station clock is the system's UTC."));
        return;
    }
    const QString clock = RehearsalMarker::clockText(m_clock->nowJulian());
    const QString rate = RehearsalMarker::rateText(m_clock->rate());
    QString text = paused ? tr("Rehearsal, paused: the station clock holds %1; Resume runs it on %2.").arg(clock, rate)
                          : tr("Rehearsal: the station clock reads %1 and runs %2.").arg(clock, rate);
    if (m_pace->follows())
        text += u' ' + tr("The simulator runs at the same rate.");
    else if (m_clock->rate() > 1.0)
        text += u' ' + tr("The rotator keeps its own pace: only the built-in simulator runs faster with the clock.");
    m_state->setText(text);
}

void TimeController::showSlider()
{
    // The operator's hand on it wins: it shows the clock again once let go.
    if (m_slider->isSliderDown())
        return;
    const double minutes = (m_clock->nowJulian() - sliderOrigin()) * kMinutesPerDay;
    const int shown = int(std::clamp(std::floor(minutes), 0.0, double(kSliderMinutes)));
    {
        const QSignalBlocker quiet(m_slider);
        m_slider->setValue(shown);
    }
    m_sliderLine->setText(QStringLiteral("%1 %2").arg(hoursAndMinutes(shown),
                                                      sky::utcFromJulian(sliderOrigin() + shown / kMinutesPerDay)
                                                          .toString(QStringLiteral("yyyy-MM-dd HH:mm 'UTC'"))));
}

} // namespace slew::ui
