// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/stationdialog.h"

#include "widgets/filechooser.h"

#include "model/settingsfile.h"
#include "sky/horizonmask.h"

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QVBoxLayout>


namespace slew::ui {

StationDialog::StationDialog(QWidget *parent)
    : QDialog(parent)
{
    setWindowTitle(tr("Station"));
    setObjectName(QStringLiteral("stationDialog"));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Where the antenna stands: latitude,longitude[,height in metres] "
                                    "or a Maidenhead locator (JO65, JO65hq, JO65hq42).")));
    m_edit = new QLineEdit;
    m_edit->setObjectName(QStringLiteral("stationEdit"));
    m_edit->setPlaceholderText(QStringLiteral("55.6875,12.625,20  or  JO65hq"));
    layout->addWidget(m_edit);
    m_feedback = new QLabel;
    m_feedback->setObjectName(QStringLiteral("stationFeedback"));
    m_feedback->setWordWrap(true);
    layout->addWidget(m_feedback);
    // What hides the sky here: a file of `azimuth elevation` lines.
    layout->addWidget(new QLabel(tr("Horizon mask (optional): a file of `azimuth elevation` lines, in degrees; "
                                    "passes rise and set on it.")));
    auto *horizonRow = new QHBoxLayout;
    m_horizon = new QLineEdit;
    m_horizon->setObjectName(QStringLiteral("stationHorizon"));
    m_horizon->setPlaceholderText(tr("none: a flat horizon"));
    auto *choose = new QPushButton(tr("Choose…"));
    choose->setObjectName(QStringLiteral("stationHorizonChoose"));
    choose->setAutoDefault(false);
    horizonRow->addWidget(m_horizon, 1);
    horizonRow->addWidget(choose);
    layout->addLayout(horizonRow);
    m_horizonFeedback = new QLabel;
    m_horizonFeedback->setObjectName(QStringLiteral("stationHorizonFeedback"));
    m_horizonFeedback->setWordWrap(true);
    layout->addWidget(m_horizonFeedback);
    connect(choose, &QPushButton::clicked, this, [this] {
        chooseFile(this, FileChoice::Open, tr("Horizon mask"), m_horizon->text(),
                   tr("Horizon masks (*.horizon *.txt);;All files (*)"),
                   [this](const QString &path) { m_horizon->setText(path); });
    });
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &StationDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &StationDialog::reject);
    connect(m_edit, &QLineEdit::textChanged, this, &StationDialog::check);
    connect(m_horizon, &QLineEdit::textChanged, this, &StationDialog::check);

    QString saved;
    savedStation(&m_station, &saved);
    m_edit->setText(saved);
    m_horizon->setText(QSettings().value(QLatin1String(sky::kHorizonSettingsKey)).toString());
    check();
}

bool StationDialog::savedStation(sky::Site *out, QString *text)
{
    const QString saved = QSettings().value(QLatin1String(sky::kSiteSettingsKey)).toString();
    if (text)
        *text = saved;
    QString error;
    return !saved.isEmpty() && sky::parseSite(saved, out, &error);
}

void StationDialog::check()
{
    QString error;
    sky::Site parsed;
    const bool ok = sky::parseSite(m_edit->text(), &parsed, &error);
    if (ok)
        m_station = parsed;
    m_feedback->setText(ok ? sky::describeSite(parsed) : error);
    m_feedback->setProperty("refused", !ok);
    // The mask is read as it is named: a file that cannot be used is said
    // here, and OK waits for a good one (or none).
    const QString path = m_horizon->text().trimmed();
    bool horizonOk = true;
    m_mask.reset();
    if (path.isEmpty()) {
        m_horizonFeedback->setText(tr("A flat horizon."));
    } else {
        const sky::HorizonFile read = sky::readHorizonFile(path);
        horizonOk = bool(read.mask);
        m_mask = read.mask;
        m_horizonFeedback->setText(horizonOk ? tr("Horizon mask: %1").arg(read.mask->describe()) : read.error);
    }
    m_horizonFeedback->setProperty("refused", !horizonOk);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(ok && horizonOk);
}

void StationDialog::accept()
{
    QString error;
    sky::Site parsed;
    if (!sky::parseSite(m_edit->text(), &parsed, &error))
        return;
    // The dialog stays open, saying why, when the settings file cannot take
    // the station: closing would claim it was kept.
    if (const QString why = model::saveSetting(QLatin1String(sky::kSiteSettingsKey), m_edit->text().trimmed());
        !why.isEmpty()) {
        m_feedback->setText(tr("The station was not saved: %1").arg(why));
        m_feedback->setProperty("refused", true);
        return;
    }
    if (const QString why = model::saveSetting(QLatin1String(sky::kHorizonSettingsKey), m_horizon->text().trimmed());
        !why.isEmpty()) {
        m_horizonFeedback->setText(tr("The horizon mask was not saved: %1").arg(why));
        m_horizonFeedback->setProperty("refused", true);
        return;
    }
    m_station = parsed;
    m_station.horizon = m_mask;
    QDialog::accept();
}

} // namespace slew::ui
