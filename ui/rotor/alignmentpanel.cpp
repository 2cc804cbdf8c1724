// SPDX-License-Identifier: GPL-3.0-or-later
#include "rotor/alignmentpanel.h"

#include "model/savedcalibration.h"
#include "session/rotatorsession.h"
#include "sky/utctime.h"
#include "tracking/skyalignment.h"

#include <QGridLayout>
#include <QLabel>
#include <QPushButton>

namespace slew::ui {

using session::RotatorSession;

AlignmentPanel::AlignmentPanel(RotatorSession *session, QWidget *parent)
    : QWidget(parent), m_session(session), m_now(&sky::julianNow)
{
    setObjectName(QStringLiteral("alignmentPanel"));
    m_offsets = new QLabel;
    m_offsets->setObjectName(QStringLiteral("alignmentOffsets"));
    m_result = new QLabel;
    m_result->setObjectName(QStringLiteral("alignmentResult"));
    m_result->setWordWrap(true);
    m_sun = new QPushButton(tr("Aligned on the sun"));
    m_sun->setObjectName(QStringLiteral("alignOnSun"));
    m_moon = new QPushButton(tr("Aligned on the moon"));
    m_moon->setObjectName(QStringLiteral("alignOnMoon"));
    m_clear = new QPushButton(tr("Clear offsets"));
    m_clear->setObjectName(QStringLiteral("clearOffsets"));
    const QString how = tr("Jog the antenna until the signal from %1 peaks (or the feed's shadow is centred), "
                           "then press: Slew sets the calibration offsets so the reading points there.");
    m_sun->setToolTip(how.arg(tr("the sun")));
    m_moon->setToolTip(how.arg(tr("the moon")));
    for (QPushButton *b : {m_sun, m_moon, m_clear}) {
        b->setAutoDefault(false);
        b->setFocusPolicy(Qt::NoFocus); // Space and Esc stay the window's Stop
    }

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->addWidget(new QLabel(tr("<b>Calibration</b>")), 0, 0);
    grid->addWidget(m_offsets, 0, 1, 1, 2);
    grid->addWidget(m_sun, 1, 0);
    grid->addWidget(m_moon, 1, 1);
    grid->addWidget(m_clear, 1, 2);
    grid->addWidget(m_result, 2, 0, 1, 3);

    connect(m_sun, &QPushButton::clicked, this, [this] { alignOn(sky::SkyBody::Sun); });
    connect(m_moon, &QPushButton::clicked, this, [this] { alignOn(sky::SkyBody::Moon); });
    connect(m_clear, &QPushButton::clicked, this, &AlignmentPanel::clearOffsets);
    connect(session, &RotatorSession::profileChanged, this, &AlignmentPanel::showOffsets);
    connect(session, &RotatorSession::stateChanged, this, &AlignmentPanel::updateButtons);
    showOffsets();
    updateButtons();
}

void AlignmentPanel::setStation(const std::optional<sky::Site> &station)
{
    m_station = station;
    updateButtons();
}

void AlignmentPanel::alignOn(sky::SkyBody body)
{
    if (!m_station) {
        m_result->setText(tr("Set the station first (Sky → Station…)."));
        return;
    }
    if (!m_session->hasPosition() || m_session->positionStale()) {
        m_result->setText(tr("The rotator's position is not known: nothing to align."));
        return;
    }
    // The controller's own reading: what the antenna points at, without the
    // offsets now in force.
    const double readingAz = m_session->azimuth() - m_session->azimuthOffset();
    const double readingEl = m_session->elevation() - m_session->elevationOffset();
    const tracking::Alignment a = tracking::alignOn(body, *m_station, m_now(), readingAz, readingEl,
                                                    !m_session->isAzimuthOnly());
    if (!a.ok()) {
        m_result->setText(tr("Not aligned: %1.").arg(a.refusal));
        return;
    }
    const double wasAz = m_session->azimuthOffset(), wasEl = m_session->elevationOffset();
    applyOffsets(a.azOffsetDeg, a.elOffsetDeg);
    const QString text = tr("Aligned on %1 at azimuth %2°, elevation %3°: offsets %4° / %5° (were %6° / %7°).")
                             .arg(body == sky::SkyBody::Sun ? tr("the sun") : tr("the moon"))
                             .arg(a.bodyAzimuthDeg, 0, 'f', 2)
                             .arg(a.bodyElevationDeg, 0, 'f', 2)
                             .arg(a.azOffsetDeg, 0, 'f', 2)
                             .arg(a.elOffsetDeg, 0, 'f', 2)
                             .arg(wasAz, 0, 'f', 2)
                             .arg(wasEl, 0, 'f', 2);
    m_result->setText(text);
    emit message(text);
}

void AlignmentPanel::clearOffsets()
{
    applyOffsets(0.0, 0.0);
    m_result->setText(tr("Calibration offsets cleared."));
    emit message(tr("calibration offsets cleared"));
}

void AlignmentPanel::applyOffsets(double az, double el)
{
    model::RotatorProfile p = m_session->profile();
    p.azOffsetDeg = az;
    p.elOffsetDeg = el;
    m_session->setProfile(p);
    if (!m_session->uri().isEmpty())
        model::saveCalibration(m_session->uri(), {az, el});
}

void AlignmentPanel::showOffsets()
{
    m_offsets->setText(tr("azimuth %1°, elevation %2°")
                           .arg(m_session->azimuthOffset(), 0, 'f', 2)
                           .arg(m_session->elevationOffset(), 0, 'f', 2));
}

void AlignmentPanel::updateButtons()
{
    const bool can = m_session->isConnected();
    m_sun->setEnabled(can);
    m_moon->setEnabled(can);
    const QString why = !m_station ? tr("Set the station first (Sky → Station…).") : QString();
    m_offsets->setToolTip(why);
}

} // namespace slew::ui
