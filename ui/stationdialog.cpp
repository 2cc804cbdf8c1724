// SPDX-License-Identifier: GPL-3.0-or-later
#include "stationdialog.h"

#include "model/settingsfile.h"

#include <QDialogButtonBox>
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
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    layout->addWidget(m_buttons);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &StationDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &StationDialog::reject);
    connect(m_edit, &QLineEdit::textChanged, this, &StationDialog::check);

    QString saved;
    savedStation(&m_station, &saved);
    m_edit->setText(saved);
    check();
}

bool StationDialog::savedStation(sky::Station *out, QString *text)
{
    const QString saved = QSettings().value(QLatin1String(sky::kStationSettingsKey)).toString();
    if (text)
        *text = saved;
    QString error;
    return !saved.isEmpty() && sky::parseStation(saved, out, &error);
}

void StationDialog::check()
{
    QString error;
    sky::Station parsed;
    const bool ok = sky::parseStation(m_edit->text(), &parsed, &error);
    if (ok)
        m_station = parsed;
    m_feedback->setText(ok ? sky::describeStation(parsed) : error);
    m_feedback->setProperty("refused", !ok);
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(ok);
}

void StationDialog::accept()
{
    QString error;
    sky::Station parsed;
    if (!sky::parseStation(m_edit->text(), &parsed, &error))
        return;
    // The dialog stays open, saying why, when the settings file cannot take
    // the station: closing would claim it was kept.
    if (const QString why = model::saveSetting(QLatin1String(sky::kStationSettingsKey), m_edit->text().trimmed());
        !why.isEmpty()) {
        m_feedback->setText(tr("The station was not saved: %1").arg(why));
        m_feedback->setProperty("refused", true);
        return;
    }
    m_station = parsed;
    QDialog::accept();
}

} // namespace slew::ui
