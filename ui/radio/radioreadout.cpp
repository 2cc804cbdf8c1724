// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radioreadout.h"

#include "radio/doppler.h"
#include "radio/dopplersteering.h"
#include "radio/frequencytext.h"
#include "station/dopplerradio.h"
#include "station/station.h"
#include "tracking/passrunner.h"
#include "tracking/stationclock.h"

#include <QFormLayout>
#include <QLabel>

#include <cmath>

namespace slew::ui {

namespace {

// Fast enough to follow a frequency the Doppler moves by up to a hundred
// hertz a second; between passes the lines change only with the clock.
constexpr int kSteeringTickMs = 250;
constexpr int kIdleTickMs = 1000;

QLabel *valueLabel(const QString &name)
{
    auto *label = new QLabel(QStringLiteral("—"));
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
}

} // namespace

RadioReadout::RadioReadout(station::Station *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    setObjectName(QStringLiteral("radioReadout"));
    m_nominal = valueLabel(QStringLiteral("radioNominal"));
    m_sent = valueLabel(QStringLiteral("radioSent"));
    m_shift = valueLabel(QStringLiteral("radioDopplerNow"));
    m_dial = valueLabel(QStringLiteral("radioDial"));
    m_figures = valueLabel(QStringLiteral("radioFigures"));
    // What the radio holds is what the operator glances at during a pass.
    QFont glance = m_sent->font();
    glance.setPointSizeF(glance.pointSizeF() * 1.15);
    glance.setBold(true);
    m_sent->setFont(glance);
    auto *form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->setVerticalSpacing(3);
    form->setRowWrapPolicy(QFormLayout::DontWrapRows);
    form->addRow(tr("Satellite"), m_nominal);
    form->addRow(tr("Radio sent"), m_sent);
    form->addRow(tr("Doppler now"), m_shift);
    form->addRow(tr("Dial"), m_dial);
    form->addRow(tr("Figures"), m_figures);

    station::DopplerRadio *radio = m_station->radio();
    connect(radio, &station::DopplerRadio::steeringChanged, this, &RadioReadout::onSteering);
    connect(&m_tick, &QTimer::timeout, this, &RadioReadout::refresh);
    m_tick.start(kIdleTickMs);
    refresh();
}

QWidget *RadioReadout::sentLine() const
{
    return m_sent;
}

void RadioReadout::onSteering(bool steering)
{
    if (steering) {
        // A new pass: what was sent in the last one is no longer on the radio.
        m_lastReceive.reset();
        m_lastTransmit.reset();
        m_lastDialHz.reset();
    }
    m_tick.start(steering ? kSteeringTickMs : kIdleTickMs);
    refresh();
}

std::optional<sky::LookAngles> RadioReadout::lookNow()
{
    const tracking::PassRunner *runner = m_station->passRunner();
    if (!runner->isRunning() || runner->target().kind != tracking::TrackTarget::Kind::Satellite) {
        m_sky.reset();
        return std::nullopt;
    }
    const tracking::TrackTarget &target = runner->target();
    if (!m_sky || m_sky->target().elements.catalogueNumber != target.elements.catalogueNumber
        || m_sky->target().elements.epochJulian() != target.elements.epochJulian())
        m_sky.emplace(target);
    return m_sky->lookAt(runner->station(), m_station->clock()->nowJulian());
}

std::optional<sky::LookAngles> RadioReadout::lookIn(double seconds)
{
    if (!m_sky)
        return std::nullopt;
    return m_sky->lookAt(m_station->passRunner()->station(), m_station->clock()->nowJulian() + seconds / 86400.0);
}

void RadioReadout::refresh()
{
    const station::DopplerRadio *radio = m_station->radio();
    const std::optional<radio::RadioPlan> &plan = radio->plan();
    if (!plan) {
        m_nominal->setText(tr("no frequencies applied"));
    } else {
        const radio::SatelliteFrequencies &f = plan->frequencies;
        auto path = [](const QString &name, double hz, double offsetHz) {
            QString text = tr("%1 %2").arg(name, radio::groupedMegahertz(hz));
            if (offsetHz != 0)
                text += tr(" (calibration %1)").arg(radio::signedHertz(offsetHz));
            return text;
        };
        QString text = path(tr("down"), f.downlinkHz, f.downlinkOffsetHz);
        if (f.uplinkHz)
            text += tr(", ") + path(tr("up"), *f.uplinkHz, f.uplinkOffsetHz);
        m_nominal->setText(text);
    }

    const radio::DopplerSteering *steering = radio->steering();
    if (radio->isSteering() && steering) {
        if (steering->sentReceiveHz())
            m_lastReceive = steering->sentReceiveHz();
        if (steering->sentTransmitHz())
            m_lastTransmit = steering->sentTransmitHz();
        if (plan)
            m_lastDialHz = steering->dialOffsetHz();
    }
    QStringList sent;
    if (m_lastReceive)
        sent << tr("receive %1").arg(radio::groupedMegahertz(*m_lastReceive));
    if (m_lastTransmit)
        sent << tr("transmit %1").arg(radio::groupedMegahertz(*m_lastTransmit));
    QString sentText = sent.isEmpty() ? tr("nothing yet") : sent.join(tr(", "));
    if (radio->isControlHeld())
        sentText = sent.isEmpty() ? tr("nothing: radio control stopped") : tr("%1; radio control stopped").arg(sentText);
    m_sent->setText(sentText);

    const std::optional<sky::LookAngles> look = lookNow();
    // A second later: how fast the shift moves (what the steering keeps up with).
    const std::optional<sky::LookAngles> later = look ? lookIn(1.0) : std::nullopt;
    if (plan && look) {
        const radio::SatelliteFrequencies &f = plan->frequencies;
        const double down = f.downlinkHz + f.downlinkOffsetHz;
        auto shift = [&](double hz, double rangeRate, bool uplink) {
            return uplink ? radio::uplinkToSendHz(hz, rangeRate) - hz : radio::downlinkOnGroundHz(hz, rangeRate) - hz;
        };
        auto path = [&](const QString &name, double hz, bool uplink) {
            QString text = tr("%1 %2").arg(name, radio::signedHertz(shift(hz, look->rangeRateKmS, uplink)));
            if (later)
                text += tr(" (%1/s)").arg(radio::signedHertz(shift(hz, later->rangeRateKmS, uplink)
                                                       - shift(hz, look->rangeRateKmS, uplink)));
            return text;
        };
        QString text = path(tr("downlink"), down, false);
        if (f.uplinkHz)
            text += tr(", ") + path(tr("uplink"), *f.uplinkHz + f.uplinkOffsetHz, true);
        // Before AOS it is what the radio will be sent first; after LOS, of
        // no use until the next pass.
        if (look->elevationDeg < 0)
            text += tr(" (below the horizon)");
        m_shift->setText(text);
    } else {
        m_shift->setText(plan ? tr("no satellite tracked") : QStringLiteral("—"));
    }

    if (!m_lastDialHz || std::abs(*m_lastDialHz) < 0.5)
        m_dial->setText(tr("not turned"));
    else
        m_dial->setText(tr("%1 on the downlink, from the plan's").arg(radio::signedHertz(*m_lastDialHz)));

    const radio::DopplerFigures figures = radio->figures();
    if (figures.samples == 0 && figures.commands == 0) {
        m_figures->setText(radio->isSteering() ? tr("this pass: none yet") : tr("no pass tuned yet"));
    } else {
        m_figures->setText(tr("%1: %2").arg(radio->isSteering() ? tr("this pass") : tr("last pass"),
                                            radio::describeFigures(figures)));
    }
}

} // namespace slew::ui
