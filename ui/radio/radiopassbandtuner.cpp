// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radiopassbandtuner.h"

#include "operatortheme.h"
#include "station/dopplerradio.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QWheelEvent>

namespace slew::ui {

namespace {

// The steps an SSB operator moves by: a kilohertz to the next station, a
// hundred hertz to clear a voice.
struct Step {
    double hz;
    const char *text;
    const char *name;
};
constexpr Step kSteps[] = {
    {-1000, QT_TRANSLATE_NOOP("slew::ui::RadioPassbandTuner", "−1 kHz"), "radioTuneDown1k"},
    {-100, QT_TRANSLATE_NOOP("slew::ui::RadioPassbandTuner", "−100 Hz"), "radioTuneDown100"},
    {100, QT_TRANSLATE_NOOP("slew::ui::RadioPassbandTuner", "+100 Hz"), "radioTuneUp100"},
    {1000, QT_TRANSLATE_NOOP("slew::ui::RadioPassbandTuner", "+1 kHz"), "radioTuneUp1k"},
};

// A wheel's notch, in the eighths of a degree QWheelEvent counts.
constexpr int kEighthsPerNotch = 120;

} // namespace

RadioPassbandTuner::RadioPassbandTuner(station::DopplerRadio *radio, QWidget *parent)
    : QWidget(parent), m_radio(radio)
{
    setObjectName(QStringLiteral("radioPassbandTuner"));
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(3);
    row->addWidget(new QLabel(tr("Tune")));
    for (const Step &step : kSteps) {
        auto *button = new QPushButton(tr(step.text));
        button->setObjectName(QString::fromLatin1(step.name));
        button->setAutoDefault(false);
        button->setToolTip(tr("Move the downlink across the passband, the uplink with it as the transponder maps it "
                              "(also the wheel over the frequencies sent)"));
        connect(button, &QPushButton::clicked, this, [this, hz = step.hz] { tuneBy(hz); });
        row->addWidget(button);
        m_steps << button;
    }
    m_refusal = new QLabel;
    m_refusal->setObjectName(QStringLiteral("radioTuneRefusal"));
    m_refusal->setStyleSheet(warningText());
    row->addWidget(m_refusal, 1);
    connect(m_radio, &station::DopplerRadio::steeringChanged, this, &RadioPassbandTuner::showEnabled);
    connect(m_radio, &station::DopplerRadio::controlHeldChanged, this, &RadioPassbandTuner::showEnabled);
    showEnabled();
}

void RadioPassbandTuner::showEnabled()
{
    const bool steering = m_radio->isSteering();
    for (QWidget *step : std::as_const(m_steps))
        step->setEnabled(steering);
    m_refusal->clear(); // a new pass, or none: the last refusal is no longer the case
}

void RadioPassbandTuner::tuneWithWheelOver(QWidget *widget)
{
    widget->installEventFilter(this);
    widget->setToolTip(tr("The wheel here tunes the downlink across the passband, %1 Hz a notch, during a pass")
                           .arg(kWheelStepHz, 0, 'f', 0));
}

bool RadioPassbandTuner::tuneBy(double hz)
{
    const QString why = m_radio->tuneBy(hz);
    m_refusal->setText(why.isEmpty() ? QString() : tr("Not tuned: %1").arg(why));
    if (!why.isEmpty())
        return false;
    emit tuned();
    return true;
}

bool RadioPassbandTuner::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() != QEvent::Wheel)
        return QWidget::eventFilter(watched, event);
    // Whole notches only: a touchpad's small deltas add up to one.
    m_wheelEighths += static_cast<QWheelEvent *>(event)->angleDelta().y();
    const int notches = int(m_wheelEighths / kEighthsPerNotch);
    if (notches != 0) {
        m_wheelEighths -= notches * kEighthsPerNotch;
        if (m_radio->isSteering())
            tuneBy(notches * kWheelStepHz);
    }
    return true; // the wheel here tunes; it scrolls nothing else
}

} // namespace slew::ui
