// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radiovfochoice.h"

#include "operatortheme.h"
#include "station/dopplerradio.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QSettings>

namespace slew::ui {

namespace {

constexpr char kLayoutKey[] = "radio/vfos";
constexpr char kRestoreKey[] = "radio/restoreAfterPass";
// The settings' words: the service's --radio-vfos takes the same.
constexpr char kSplitWord[] = "split";
constexpr char kMainSubWord[] = "main-sub";

} // namespace

RadioVfoChoice::RadioVfoChoice(station::DopplerRadio *radio, QWidget *parent) : QWidget(parent), m_radio(radio)
{
    setObjectName(QStringLiteral("radioVfoChoice"));
    m_layout = new QComboBox;
    m_layout->setObjectName(QStringLiteral("radioVfos"));
    m_layout->addItem(tr("split: VFO A receives, VFO B transmits"), QString::fromLatin1(kSplitWord));
    m_layout->addItem(tr("satellite mode: Sub receives, Main transmits"), QString::fromLatin1(kMainSubWord));
    // Its choices whole: on a narrow screen the Radio page scrolls instead.
    m_layout->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_layout->setToolTip(tr("Split for most radios (Slew turns it on at AOS). Satellite mode for an IC-9700 "
                            "and its kind with satellite mode on at the radio; through rigctld, start rigctld with -o (VFO mode)."));
    m_restore = new QCheckBox(tr("Put it back after LOS"));
    m_restore->setObjectName(QStringLiteral("radioRestore"));
    m_restore->setToolTip(tr("After each pass, the receive frequency the radio was found on before AOS, "
                             "and split off again if Slew turned it on"));
    m_refusal = new QLabel;
    m_refusal->setObjectName(QStringLiteral("radioVfoRefusal"));
    m_refusal->setWordWrap(true);
    m_refusal->setStyleSheet(refusedText());
    m_refusal->hide();

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setVerticalSpacing(3);
    // The check box under the choice: beside it, the two would not fit
    // the Radio page at 1280x720 without scrolling.
    grid->addWidget(new QLabel(tr("VFOs")), 0, 0);
    grid->addWidget(m_layout, 0, 1);
    grid->addWidget(m_restore, 1, 1, Qt::AlignLeft); // as wide as its words: a click beside them is not on it
    grid->addWidget(m_refusal, 2, 0, 1, 2);
    grid->setColumnStretch(1, 1);

    const QSettings settings;
    const bool mainSub = settings.value(QLatin1String(kLayoutKey)).toString() == QLatin1String(kMainSubWord);
    m_layout->setCurrentIndex(mainSub ? 1 : 0);
    m_restore->setChecked(settings.value(QLatin1String(kRestoreKey), false).toBool());
    m_radio->setRestoreAfterPass(m_restore->isChecked());
    applyToLink();
    connect(m_layout, &QComboBox::currentIndexChanged, this, &RadioVfoChoice::onLayoutChosen);
    connect(m_restore, &QCheckBox::toggled, this, &RadioVfoChoice::onRestoreToggled);
}

void RadioVfoChoice::applyToLink()
{
    const bool mainSub = m_layout->currentData().toString() == QLatin1String(kMainSubWord);
    const QString why = m_radio->setVfoLayout(mainSub ? radio::VfoLayout::MainSub : radio::VfoLayout::Split);
    m_refusal->setVisible(!why.isEmpty());
    m_refusal->setText(why.isEmpty() ? QString() : tr("%1; the radio keeps split").arg(why));
    if (!why.isEmpty())
        emit message(tr("radio: %1").arg(m_refusal->text()));
}

void RadioVfoChoice::onLayoutChosen()
{
    QSettings().setValue(QLatin1String(kLayoutKey), m_layout->currentData().toString());
    applyToLink();
    if (m_refusal->isHidden())
        emit message(tr("radio: VFOs: %1, from the radio's next opening").arg(m_layout->currentText()));
}

void RadioVfoChoice::onRestoreToggled(bool restore)
{
    QSettings().setValue(QLatin1String(kRestoreKey), restore);
    m_radio->setRestoreAfterPass(restore);
    emit message(restore ? tr("radio: put back as it was found after each pass")
                         : tr("radio: left where each pass ends"));
}

} // namespace slew::ui
