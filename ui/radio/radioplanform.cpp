// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radioplanform.h"

#include "operatortheme.h"
#include "radio/frequencytext.h"
#include "station/radiooptions.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace slew::ui {

namespace {


// The combo's entry whose data is `word`, else the first.
void chooseWord(QComboBox *combo, const QString &word)
{
    const int index = combo->findData(word.trimmed().toLower());
    combo->setCurrentIndex(index >= 0 ? index : 0);
}

} // namespace

RadioPlanForm::RadioPlanForm(QWidget *parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("radioPlanForm"));
    m_transponder = new QComboBox;
    m_transponder->setObjectName(QStringLiteral("radioTransponder"));
    setTransponders({});
    connect(m_transponder, &QComboBox::activated, this, [this](int item) {
        if (item > 0)
            pickTransponder(item - 1);
    });

    m_downlink = addFrequencyField(QStringLiteral("radioDownlink"), tr("435.85M"),
                                   tr("What the satellite sends on: 145.8M, 435.125 MHz, 1296200k, or hertz"));
    m_uplink = addFrequencyField(QStringLiteral("radioUplink"), tr("none"),
                                 tr("What the satellite listens on, if the radio is to transmit; empty: receive only"));
    m_downlinkOffset = addFrequencyField(QStringLiteral("radioDownlinkOffset"), tr("0 Hz"),
                                         tr("Calibration added to the downlink (the satellite's crystal drifts): "
                                            "-1.2k, 350 (Hz), within ±1 MHz"));
    m_uplinkOffset = addFrequencyField(QStringLiteral("radioUplinkOffset"), tr("0 Hz"),
                                       tr("Calibration added to the uplink: -1.2k, 350 (Hz), within ±1 MHz"));
    m_receiveMode = addModeField(QStringLiteral("radioReceiveMode"), tr("The receive mode (a Hamlib name); empty: "
                                                                        "left as the radio has it"));
    m_transmitMode = addModeField(QStringLiteral("radioTransmitMode"), tr("The transmit mode with an uplink (a Hamlib "
                                                                          "name); empty: left as the radio has it"));
    m_doppler = new QComboBox;
    m_doppler->setObjectName(QStringLiteral("radioDoppler"));
    m_doppler->addItem(tr("both paths"), QStringLiteral("both"));
    m_doppler->addItem(tr("downlink only"), QStringLiteral("downlink"));
    m_doppler->addItem(tr("uplink only"), QStringLiteral("uplink"));
    m_doppler->setToolTip(tr("Which frequencies Slew corrects; some operators tune the downlink by ear"));
    m_follows = new QComboBox;
    m_follows->setObjectName(QStringLiteral("radioUplinkFollows"));
    m_follows->addItem(tr("no"), QStringLiteral("no"));
    m_follows->addItem(tr("the same way"), QStringLiteral("same"));
    m_follows->addItem(tr("the opposite way"), QStringLiteral("opposite"));
    m_follows->setToolTip(tr("When you turn the downlink on the radio's dial: a fixed channel (no), a "
                             "non-inverting linear transponder (the same way), an inverting one (the opposite way)"));

    m_downlinkError = addError(QStringLiteral("radioDownlinkError"));
    m_receiveModeError = addError(QStringLiteral("radioReceiveModeError"));
    m_downlinkOffsetError = addError(QStringLiteral("radioDownlinkOffsetError"));
    m_uplinkError = addError(QStringLiteral("radioUplinkError"));
    m_transmitModeError = addError(QStringLiteral("radioTransmitModeError"));
    m_uplinkOffsetError = addError(QStringLiteral("radioUplinkOffsetError"));
    m_dopplerError = addError(QStringLiteral("radioDopplerError"));

    // One row per path: frequency, mode, calibration; the refusals of a
    // row right under it, across the form, where a long one can wrap.
    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(6);
    grid->setVerticalSpacing(3);
    grid->addWidget(new QLabel(tr("Transponder")), 0, 0);
    grid->addWidget(m_transponder, 0, 1, 1, 3);
    grid->addWidget(new QLabel(tr("Frequency")), 1, 1);
    grid->addWidget(new QLabel(tr("Mode")), 1, 2);
    grid->addWidget(new QLabel(tr("Calibration")), 1, 3);
    auto errorsUnder = [grid](int row, std::initializer_list<QLabel *> errors) {
        auto *column = new QVBoxLayout;
        column->setContentsMargins(0, 0, 0, 0);
        column->setSpacing(0);
        for (QLabel *e : errors)
            column->addWidget(e);
        grid->addLayout(column, row, 0, 1, 4);
    };
    grid->addWidget(new QLabel(tr("Downlink")), 2, 0);
    grid->addWidget(m_downlink, 2, 1);
    grid->addWidget(m_receiveMode, 2, 2);
    grid->addWidget(m_downlinkOffset, 2, 3);
    errorsUnder(3, {m_downlinkError, m_receiveModeError, m_downlinkOffsetError});
    grid->addWidget(new QLabel(tr("Uplink")), 4, 0);
    grid->addWidget(m_uplink, 4, 1);
    grid->addWidget(m_transmitMode, 4, 2);
    grid->addWidget(m_uplinkOffset, 4, 3);
    errorsUnder(5, {m_uplinkError, m_transmitModeError, m_uplinkOffsetError});
    grid->addWidget(new QLabel(tr("Doppler on")), 6, 0);
    grid->addWidget(m_doppler, 6, 1, 1, 3, Qt::AlignLeft);
    errorsUnder(7, {m_dopplerError});
    grid->addWidget(new QLabel(tr("Uplink follows dial")), 8, 0);
    grid->addWidget(m_follows, 8, 1, 1, 3, Qt::AlignLeft);
    // The frequency takes what width there is; mode and calibration are short.
    grid->setColumnStretch(1, 3);
    grid->setColumnStretch(2, 1);
    grid->setColumnStretch(3, 2);
}

void RadioPlanForm::setTransponders(const QList<radio::Transponder> &transponders)
{
    m_transponders = transponders;
    m_transponder->clear();
    m_transponder->addItem(tr("frequencies by hand"));
    for (const radio::Transponder &t : transponders) {
        QString item = t.displayName();
        if (t.downlinkLowHz)
            item += QStringLiteral(" · %1").arg(radio::groupedMegahertz(*t.downlinkLowHz));
        if (!t.mode.isEmpty())
            item += QLatin1Char(' ') + t.mode;
        if (!t.alive)
            item += tr(" (not alive)");
        m_transponder->addItem(item);
    }
    m_transponder->setEnabled(!transponders.isEmpty());
    m_transponder->setToolTip(transponders.isEmpty()
                                  ? tr("no transponders known for this satellite (Refresh transponders, or slew "
                                       "--update-transponders)")
                                  : tr("Fill the fields from one of the satellite's transponders"));
}

void RadioPlanForm::pickTransponder(int index)
{
    if (index < 0 || index >= m_transponders.size())
        return;
    QString note, why;
    const std::optional<radio::RadioPlan> plan = radio::planFor(m_transponders[index], &note, &why);
    clearRefusals();
    if (!plan) {
        refuse(m_transponder, m_downlinkError, why);
        return;
    }
    m_transponder->setCurrentIndex(index + 1);
    // Megahertz to the hertz, without trailing zeros: what an operator types.
    auto megahertz = [](double hz) {
        QString text = QString::number(hz / 1e6, 'f', 6);
        while (text.endsWith(u'0'))
            text.chop(1);
        if (text.endsWith(u'.'))
            text.chop(1);
        return text + QLatin1Char('M');
    };
    RadioPlanTexts t = texts(); // the calibration and the paths stay the operator's
    t.downlink = megahertz(plan->frequencies.downlinkHz);
    t.uplink = plan->frequencies.uplinkHz ? megahertz(*plan->frequencies.uplinkHz) : QString();
    t.receiveMode = plan->receiveMode;
    t.transmitMode = plan->transmitMode;
    switch (plan->frequencies.uplinkFollows) {
    case radio::UplinkFollowsDial::No:
        t.uplinkFollows = QStringLiteral("no");
        break;
    case radio::UplinkFollowsDial::SameWay:
        t.uplinkFollows = QStringLiteral("same");
        break;
    case radio::UplinkFollowsDial::OppositeWay:
        t.uplinkFollows = QStringLiteral("opposite");
        break;
    }
    setTexts(t);
    if (!note.isEmpty())
        emit noted(tr("%1: %2").arg(m_transponders[index].displayName(), note));
}

QLineEdit *RadioPlanForm::addFrequencyField(const QString &name, const QString &placeholder, const QString &tip)
{
    auto *field = new QLineEdit;
    field->setObjectName(name);
    field->setPlaceholderText(placeholder);
    field->setToolTip(tip);
    connect(field, &QLineEdit::returnPressed, this, &RadioPlanForm::applyAsked);
    return field;
}

QComboBox *RadioPlanForm::addModeField(const QString &name, const QString &tip)
{
    auto *combo = new QComboBox;
    combo->setObjectName(name);
    combo->setEditable(true);
    combo->setInsertPolicy(QComboBox::NoInsert);
    for (const char *mode : {"", "USB", "LSB", "CW", "FM", "AM"})
        combo->addItem(QString::fromLatin1(mode));
    combo->lineEdit()->setPlaceholderText(tr("as set"));
    // Room for the longest name Hamlib gives a mode (8 characters, PKTUSB
    // and the like) and for a slip as long, which is then refused whole.
    combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    combo->setMinimumContentsLength(8);
    combo->setToolTip(tip);
    connect(combo->lineEdit(), &QLineEdit::returnPressed, this, &RadioPlanForm::applyAsked);
    return combo;
}

QLabel *RadioPlanForm::addError(const QString &name)
{
    auto *label = new QLabel;
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setStyleSheet(refusedText());
    label->hide();
    return label;
}

void RadioPlanForm::setTexts(const RadioPlanTexts &t)
{
    clearRefusals();
    m_downlink->setText(t.downlink);
    m_uplink->setText(t.uplink);
    m_receiveMode->setCurrentText(t.receiveMode);
    m_transmitMode->setCurrentText(t.transmitMode);
    m_downlinkOffset->setText(t.downlinkOffset);
    m_uplinkOffset->setText(t.uplinkOffset);
    chooseWord(m_doppler, t.doppler);
    chooseWord(m_follows, t.uplinkFollows);
}

RadioPlanTexts RadioPlanForm::texts() const
{
    RadioPlanTexts t;
    t.downlink = m_downlink->text().trimmed();
    t.uplink = m_uplink->text().trimmed();
    t.receiveMode = m_receiveMode->currentText().trimmed().toUpper();
    t.transmitMode = m_transmitMode->currentText().trimmed().toUpper();
    t.downlinkOffset = m_downlinkOffset->text().trimmed();
    t.uplinkOffset = m_uplinkOffset->text().trimmed();
    t.doppler = m_doppler->currentData().toString();
    t.uplinkFollows = m_follows->currentData().toString();
    return t;
}

void RadioPlanForm::refuse(QWidget *field, QLabel *error, const QString &why)
{
    field->setStyleSheet(refusedField() + QLatin1Char(' ') + refusedField("QComboBox"));
    error->setText(why);
    error->show();
}

void RadioPlanForm::clearRefusals()
{
    for (QWidget *field : std::initializer_list<QWidget *>{m_downlink, m_uplink, m_downlinkOffset, m_uplinkOffset,
                                                           m_receiveMode, m_transmitMode, m_doppler})
        field->setStyleSheet(QString());
    for (QLabel *error : {m_downlinkError, m_uplinkError, m_receiveModeError, m_transmitModeError,
                          m_downlinkOffsetError, m_uplinkOffsetError, m_dopplerError}) {
        error->clear();
        error->hide();
    }
}

bool RadioPlanForm::showsRefusal() const
{
    for (const QLabel *error : {m_downlinkError, m_uplinkError, m_receiveModeError, m_transmitModeError,
                                m_downlinkOffsetError, m_uplinkOffsetError, m_dopplerError})
        if (!error->isHidden())
            return true;
    return false;
}

std::optional<radio::RadioPlan> RadioPlanForm::readPlan(int noradId)
{
    clearRefusals();
    const RadioPlanTexts t = texts();
    // Each field read the way the station service reads its option, so a
    // frequency the service takes the panel takes, in the same words.
    station::RadioOptions options;
    bool ok = true;
    QString why;
    if (t.downlink.isEmpty()) {
        refuse(m_downlink, m_downlinkError, tr("Downlink: the frequency the satellite sends on is needed (435.85M)"));
        ok = false;
    } else if (const std::optional<double> hz = radio::parseFrequency(t.downlink, &why)) {
        options.downlinkHz = hz;
    } else {
        refuse(m_downlink, m_downlinkError, tr("Downlink: %1").arg(why));
        ok = false;
    }
    if (!t.uplink.isEmpty()) {
        if (const std::optional<double> hz = radio::parseFrequency(t.uplink, &why)) {
            options.uplinkHz = hz;
        } else {
            refuse(m_uplink, m_uplinkError, tr("Uplink: %1").arg(why));
            ok = false;
        }
    }
    auto readMode = [&](const QString &text, QComboBox *field, QLabel *error, const QString &what, QString *into) {
        if (text.isEmpty())
            return;
        if (const std::optional<QString> mode = radio::parseModeName(text, &why)) {
            *into = *mode;
        } else {
            refuse(field, error, tr("%1: %2").arg(what, why));
            ok = false;
        }
    };
    readMode(t.receiveMode, m_receiveMode, m_receiveModeError, tr("Receive mode"), &options.downlinkMode);
    readMode(t.transmitMode, m_transmitMode, m_transmitModeError, tr("Transmit mode"), &options.uplinkMode);
    auto readOffset = [&](const QString &text, QLineEdit *field, QLabel *error, const QString &what, double *into) {
        if (text.isEmpty())
            return;
        if (const std::optional<double> hz = radio::parseFrequencyOffset(text, &why)) {
            *into = *hz;
        } else {
            refuse(field, error, tr("%1: %2").arg(what, why));
            ok = false;
        }
    };
    readOffset(t.downlinkOffset, m_downlinkOffset, m_downlinkOffsetError, tr("Downlink calibration"),
               &options.downlinkOffsetHz);
    readOffset(t.uplinkOffset, m_uplinkOffset, m_uplinkOffsetError, tr("Uplink calibration"), &options.uplinkOffsetHz);
    // The two lists offer only what these read.
    options.correct = station::parseDopplerOn(t.doppler, &why).value_or(radio::DopplerOn::Both);
    options.uplinkFollows = station::parseUplinkFollows(t.uplinkFollows, &why);
    if (!ok)
        return std::nullopt;
    // What is wrong only in the whole (Doppler on an uplink that is not
    // there) the service's rules say too.
    QStringList notes;
    std::optional<radio::RadioPlan> plan = station::resolveRadioPlan(options, noradId, &notes, &why);
    if (!plan)
        refuse(m_doppler, m_dopplerError, why);
    else if (!plan->frequencies.downlinkPassband) // typed, or kept: the passband of the transponder it is on
        plan->frequencies.downlinkPassband = radio::passbandAround(m_transponders, plan->frequencies.downlinkHz);
    return plan;
}

} // namespace slew::ui
