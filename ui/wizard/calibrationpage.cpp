// SPDX-License-Identifier: GPL-3.0-or-later
#include "wizard/calibrationpage.h"

#include "wizard/pagebody.h"
#include "wizard/setupwizard.h"

#include "protocol/operations.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace slew::ui {

using session::RotatorSession;
using Point = session::Micro2gCalibration::Point;

namespace {

constexpr double kRestSeconds = 2.0; // unchanged this long: the rotor is at rest
constexpr int kRestCounts = 1;       // a reading may flicker by a count at rest
constexpr int kAdcSlack = 2;         // read back within this of the reading sent: as sent

QPushButton *button(const QString &text, const char *name, QWidget *parent)
{
    auto *b = new QPushButton(text, parent);
    b->setObjectName(QLatin1String(name));
    return b;
}

QSpinBox *spinBox(int min, int max, int value, const char *name, QWidget *parent)
{
    auto *s = new QSpinBox(parent);
    s->setObjectName(QLatin1String(name));
    s->setRange(min, max);
    s->setValue(value);
    s->setSuffix(QStringLiteral("°"));
    return s;
}

QLabel *wrappingLabel(const char *name, QWidget *parent)
{
    auto *l = new QLabel(parent);
    l->setObjectName(QLatin1String(name));
    l->setWordWrap(true);
    return l;
}

// Whether the controller holds a stop as it was sent: its own reading of
// the stop (within a count or two of the one the page showed) and the
// bearing entered.
bool stopAsSent(std::optional<int> sentAdc, std::optional<int> sentBearing, int heldAdc, int heldBearing)
{
    return sentAdc && sentBearing && std::abs(*sentAdc - heldAdc) <= kAdcSlack && *sentBearing == heldBearing;
}

QString threeDigits(int degrees)
{
    return QStringLiteral("%1").arg(degrees, 3, 10, QLatin1Char('0'));
}

} // namespace

bool CalibrationPage::appliesTo(const SetupWizard *wizard)
{
    // The controllers that take a two-point calibration by `Z`.
    return protocol::dialectSupports(wizard->profile().dialect, protocol::Op::Calibration);
}

CalibrationPage::CalibrationPage(SetupWizard *wizard) : QWizardPage(wizard), m_wizard(wizard)
{
    setTitle(tr("Calibration"));
    setSubTitle(tr("The controller reads the rotor's position as an A/D value; two end stops and the degrees "
                   "between them turn that into a bearing."));
    m_rotorNote = wrappingLabel("calibrationRotor", this);
    auto *how = wrappingLabel("calibrationHow", this);
    how->setText(tr("Turn the rotor with the switch on its control box and hold it until the rotor stops at its "
                    "end stop. Slew does not drive it there: until the rotor is calibrated, a go-to aims with "
                    "the very calibration being replaced."));
    m_reading = wrappingLabel("adcReading", this);
    m_heading = wrappingLabel("calibrationHeading", this);

    m_leftBearing = spinBox(0, 359, 0, "leftBearing", this);
    m_setLeft = button(tr("Set the left stop here"), "setLeft", this);
    m_rightBearing = spinBox(0, 359, 90, "rightBearing", this);
    m_setRight = button(tr("Set the right stop here"), "setRight", this);
    m_range = spinBox(90, 540, 450, "degreeRange", this);
    m_setRange = button(tr("Set the range"), "setRange", this);
    m_readBack = button(tr("Read back"), "readBack", this);
    m_heldText = wrappingLabel("calibrationHeld", this);
    m_heldText->setTextFormat(Qt::RichText);
    m_status = wrappingLabel("calibrationStatus", this);
    m_skip = new QCheckBox(tr("Skip: the controller is calibrated already"), this);
    m_skip->setObjectName(QStringLiteral("skipCalibration"));

    auto step = [this](const QString &title, const QString &text, QWidget *field, const QString &label,
                       QPushButton *action) {
        auto *box = new QGroupBox(title, this);
        auto *intro = new QLabel(text, box);
        intro->setWordWrap(true);
        auto *row = new QHBoxLayout;
        row->addWidget(new QLabel(label, box));
        row->addWidget(field);
        row->addWidget(action);
        row->addStretch();
        auto *layout = new QVBoxLayout(box);
        layout->addWidget(intro);
        layout->addLayout(row);
        return box;
    };
    auto *live = new QGroupBox(tr("The rotor now"), this);
    auto *liveLayout = new QFormLayout(live);
    liveLayout->addRow(tr("A/D reading"), m_reading);
    liveLayout->addRow(tr("Heading"), m_heading);

    auto *layout = new QVBoxLayout(makePageBody(this));
    layout->addWidget(m_rotorNote);
    layout->addWidget(how);
    layout->addWidget(live);
    layout->addWidget(step(tr("1. Left (counter-clockwise) stop"),
                           tr("Turn the rotor left until it stops, then enter the bearing the antenna points to."),
                           m_leftBearing, tr("Bearing there"), m_setLeft));
    layout->addWidget(step(tr("2. Right (clockwise) stop"),
                           tr("Turn the rotor right until it stops, then enter the bearing there."), m_rightBearing,
                           tr("Bearing there"), m_setRight));
    layout->addWidget(step(tr("3. Travel"), tr("The degrees the rotor turns from the left stop to the right."),
                           m_range, tr("Degrees"), m_setRange));
    auto *held = new QGroupBox(tr("4. What the controller holds"), this);
    auto *heldLayout = new QVBoxLayout(held);
    auto *heldRow = new QHBoxLayout;
    heldRow->addWidget(m_heldText, 1);
    heldRow->addWidget(m_readBack, 0, Qt::AlignTop);
    heldLayout->addLayout(heldRow);
    layout->addWidget(held);
    layout->addWidget(m_status);
    layout->addWidget(m_skip);
    layout->addStretch();

    connect(m_setLeft, &QPushButton::clicked, this, [this] { send(Point::LeftStop, m_leftBearing->value()); });
    connect(m_setRight, &QPushButton::clicked, this, [this] { send(Point::RightStop, m_rightBearing->value()); });
    connect(m_setRange, &QPushButton::clicked, this, [this] { send(Point::DegreeRange, m_range->value()); });
    connect(m_readBack, &QPushButton::clicked, this, [this] {
        if (const auto asked = m_wizard->session()->micro2g()->request(m_rotor); !asked) {
            setStatus(asked.refusal, true);
            return;
        }
        m_before = m_sent;
        m_waiting = true;
        m_alarm.clear();
        updateControls();
    });
    connect(m_skip, &QCheckBox::toggled, this, &CalibrationPage::completeChanged);

    RotatorSession *s = wizard->session();
    connect(s, &RotatorSession::positionChanged, this, &CalibrationPage::onPosition);
    connect(s->micro2g(), &session::Micro2gCalibration::adcReadingReceived, this, &CalibrationPage::onReading);
    connect(s->micro2g(), &session::Micro2gCalibration::calibrationReceived, this, &CalibrationPage::onCalibration);
    connect(s->micro2g(), &session::Micro2gCalibration::calibrationFailed, this, &CalibrationPage::onRefused);
    connect(s, &RotatorSession::alarmReceived, this, [this](const QString &text) {
        if (m_waiting)
            m_alarm = text;
    });
    connect(s, &RotatorSession::stateChanged, this, &CalibrationPage::updateControls);
}

void CalibrationPage::initializePage()
{
    const RotatorSession *s = m_wizard->session();
    m_rotor = s->rotor() > 0 ? s->rotor() : 1;
    m_rotorNote->setText(s->rotor() > 0
                             ? tr("Calibrating rotor %1, the one the link names (rotor=%1).").arg(m_rotor)
                             : tr("The link names no rotor (rotor=n on its address), so this page calibrates "
                                  "rotor 1. The heading shown is that of the controller's default rotor."));
    m_recent.clear();
    m_sent = {};
    m_held.reset();
    m_waiting = false;
    setStatus({}, false);
    m_heldText->setText(tr("Reading the calibration…"));
    if (const auto asked = m_wizard->session()->micro2g()->request(m_rotor))
        m_waiting = true;
    else
        m_heldText->setText(asked.refusal);
    updateControls();
}

bool CalibrationPage::isActive() const
{
    return m_wizard->currentPage() == this;
}

int CalibrationPage::readingsForRest() const
{
    const int pollHz = std::clamp(m_wizard->session()->profile().pollHz, 1, 50);
    return std::max(3, int(std::ceil(kRestSeconds * pollHz)));
}

void CalibrationPage::onPosition()
{
    // A reading for every position the session polls: the readings keep
    // the session's pace (and its clock), whatever the link.
    if (isActive())
        m_wizard->session()->micro2g()->requestAdcReadings();
    updateControls();
}

void CalibrationPage::onReading(int rotor, int counts)
{
    if (rotor != m_rotor || !isActive())
        return;
    m_recent.append(counts);
    while (m_recent.size() > readingsForRest())
        m_recent.removeFirst();
    updateControls();
}

bool CalibrationPage::atRest() const
{
    if (m_recent.size() < readingsForRest())
        return false;
    const auto [low, high] = std::minmax_element(m_recent.begin(), m_recent.end());
    return *high - *low <= kRestCounts;
}

void CalibrationPage::send(Point point, int value)
{
    if (point != Point::DegreeRange && !atRest()) {
        setStatus(tr("Wait until the rotor is at rest at its stop."), true);
        return;
    }
    const auto sent = m_wizard->session()->micro2g()->set(m_rotor, point, value);
    if (!sent) {
        setStatus(sent.refusal, true);
        return;
    }
    m_before = m_sent;
    // Remember what was meant, to compare with the read-back; the
    // controller records its own reading, which should be the one shown.
    switch (point) {
    case Point::LeftStop:
        m_sent.leftAdc = m_recent.last();
        m_sent.leftBearing = value;
        break;
    case Point::RightStop:
        m_sent.rightAdc = m_recent.last();
        m_sent.rightBearing = value;
        break;
    case Point::DegreeRange:
        m_sent.degreeRange = value;
        break;
    }
    m_waiting = true;
    m_alarm.clear();
    setStatus(tr("Sent; reading back…"), false);
    updateControls();
}

void CalibrationPage::onCalibration(int rotor, const protocol::Micro2gCalibration &held)
{
    if (rotor != m_rotor)
        return;
    m_held = held;
    const bool answered = m_waiting && m_alarm.isEmpty();
    m_waiting = false;
    m_heldText->setText(describeHeld());
    if (answered) {
        const bool same = !differsFromSent();
        setStatus(isComplete() ? tr("Calibrated: the controller holds both stops and the travel as sent.")
                      : same   ? tr("The controller holds what was sent so far (read back above).")
                               : tr("The controller holds something other than what was sent: see above."),
                  !same);
    }
    updateControls();
}

void CalibrationPage::onRefused(int rotor, const QString &reason)
{
    if (rotor != m_rotor)
        return;
    m_waiting = false;
    if (m_alarm.isEmpty()) {
        setStatus(tr("No answer from the controller (%1). Press Read back to see what it holds.").arg(reason), true);
    } else {
        // Refused, so not the controller's: what it holds is compared with
        // what was sent before. (The `Z` on the same request reads it back.)
        m_sent = m_before;
        QString text = tr("The controller refused this and kept the calibration it had: %1.").arg(m_alarm);
        if (m_alarm.contains(QStringLiteral("10 counts")))
            text += tr(" Both stops would read nearly the same: turn the rotor to the other stop before setting it.");
        setStatus(text, true);
    }
    m_heldText->setText(describeHeld());
    updateControls();
}

void CalibrationPage::setStatus(const QString &text, bool problem)
{
    m_status->setText(text);
    m_status->setStyleSheet(problem ? QStringLiteral("color: #b00000") : QString());
}

QString CalibrationPage::describeHeld() const
{
    if (!m_held)
        return tr("Not read yet.");
    const protocol::Micro2gCalibration &c = *m_held;
    auto row = [](const QString &what, const QString &holds, const QString &verdict) {
        return QStringLiteral("<tr><td>%1</td><td>&nbsp;%2&nbsp;</td><td>%3</td></tr>").arg(what, holds, verdict);
    };
    auto verdict = [](bool sent, bool same, const QString &wanted) {
        if (!sent)
            return QString();
        return same ? tr("as sent") : tr("<b style=\"color:#b00000\">differs: sent %1</b>").arg(wanted);
    };
    const Sent &s = m_sent;
    const bool leftSame = stopAsSent(s.leftAdc, s.leftBearing, c.leftAdc, c.leftBearing);
    const bool rightSame = stopAsSent(s.rightAdc, s.rightBearing, c.rightAdc, c.rightBearing);
    QString table = QStringLiteral("<table>");
    table += row(tr("Left stop"), tr("reads %1 at %2°").arg(c.leftAdc).arg(threeDigits(c.leftBearing)),
                 verdict(s.leftAdc.has_value(), leftSame,
                         tr("%1 at %2°").arg(s.leftAdc.value_or(0)).arg(threeDigits(s.leftBearing.value_or(0)))));
    table += row(tr("Right stop"), tr("reads %1 at %2°").arg(c.rightAdc).arg(threeDigits(c.rightBearing)),
                 verdict(s.rightAdc.has_value(), rightSame,
                         tr("%1 at %2°").arg(s.rightAdc.value_or(0)).arg(threeDigits(s.rightBearing.value_or(0)))));
    table += row(tr("Travel"), tr("%1°").arg(c.degreeRange),
                 verdict(s.degreeRange.has_value(), s.degreeRange == c.degreeRange,
                         tr("%1°").arg(s.degreeRange.value_or(0))));
    table += QStringLiteral("</table>");
    return tr("Rotor %1 (Z%1L %2=%3 Z%1R %4=%5 Z%1D %6):")
               .arg(c.rotor)
               .arg(c.leftAdc)
               .arg(threeDigits(c.leftBearing))
               .arg(c.rightAdc)
               .arg(threeDigits(c.rightBearing))
               .arg(c.degreeRange)
        + table;
}

void CalibrationPage::updateControls()
{
    const RotatorSession *s = m_wizard->session();
    const bool connected = s->isConnected();
    const bool rest = atRest();
    if (m_recent.isEmpty())
        m_reading->setText(tr("waiting for the first reading…"));
    else
        m_reading->setText(tr("%1 counts: %2")
                               .arg(m_recent.last())
                               .arg(rest ? tr("at rest") : m_recent.size() < readingsForRest()
                                        ? tr("watching whether it is still turning…")
                                        : tr("turning")));
    m_heading->setText(s->hasPosition() ? tr("%1°").arg(s->azimuth(), 0, 'f', 0) : tr("unknown"));
    const bool free = connected && !m_waiting;
    m_setLeft->setEnabled(free && rest);
    m_setRight->setEnabled(free && rest);
    m_setRange->setEnabled(free);
    m_readBack->setEnabled(free);
    emit completeChanged();
}

bool CalibrationPage::differsFromSent() const
{
    if (!m_held)
        return false;
    const Sent &s = m_sent;
    const protocol::Micro2gCalibration &c = *m_held;
    return (s.leftAdc && !stopAsSent(s.leftAdc, s.leftBearing, c.leftAdc, c.leftBearing))
        || (s.rightAdc && !stopAsSent(s.rightAdc, s.rightBearing, c.rightAdc, c.rightBearing))
        || (s.degreeRange && *s.degreeRange != c.degreeRange);
}

bool CalibrationPage::isComplete() const
{
    if (m_waiting)
        return false;
    if (m_skip->isChecked())
        return true;
    const bool allSent = m_sent.leftAdc && m_sent.rightAdc && m_sent.degreeRange;
    return m_held && allSent && !differsFromSent();
}

} // namespace slew::ui
