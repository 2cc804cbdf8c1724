// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/remotecontrols.h"

#include "operatortheme.h"
#include "input/finitenumber.h"
#include "remote/remotestation.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace slew::ui {

using remote::RemoteStation;

namespace {

std::optional<double> fieldValue(const QLineEdit *field)
{
    QString text = field->text().trimmed();
    text.replace(u',', u'.');
    return input::finiteNumber(text);
}

} // namespace

RemoteControls::RemoteControls(RemoteStation *station, QWidget *parent) : QWidget(parent), m_station(station)
{
    m_az = new QLineEdit;
    m_az->setObjectName(QStringLiteral("remoteGotoAz"));
    m_az->setPlaceholderText(tr("az °"));
    m_el = new QLineEdit;
    m_el->setObjectName(QStringLiteral("remoteGotoEl"));
    m_el->setPlaceholderText(tr("el °"));
    m_go = new QPushButton(tr("Go"));
    m_go->setObjectName(QStringLiteral("remoteGo"));
    auto *gotoRow = new QHBoxLayout;
    gotoRow->addWidget(new QLabel(tr("Go to")));
    gotoRow->addWidget(m_az);
    gotoRow->addWidget(m_el);
    gotoRow->addWidget(m_go);

    m_speed = new QDoubleSpinBox;
    m_speed->setObjectName(QStringLiteral("remoteJogSpeed"));
    m_speed->setRange(0.5, remote::kFastestJog);
    m_speed->setValue(5.0);
    m_speed->setSuffix(tr(" °/s"));
    auto *jogGrid = new QGridLayout;
    jogGrid->addWidget(jogButton(QStringLiteral("▲"), QStringLiteral("remoteJogUp"), 0, 1), 0, 1);
    jogGrid->addWidget(jogButton(QStringLiteral("◀"), QStringLiteral("remoteJogLeft"), -1, 0), 1, 0);
    jogGrid->addWidget(m_speed, 1, 1);
    jogGrid->addWidget(jogButton(QStringLiteral("▶"), QStringLiteral("remoteJogRight"), 1, 0), 1, 2);
    jogGrid->addWidget(jogButton(QStringLiteral("▼"), QStringLiteral("remoteJogDown"), 0, -1), 2, 1);

    m_park = new QPushButton(tr("Park"));
    m_park->setObjectName(QStringLiteral("remotePark"));
    m_home = new QPushButton(tr("Home"));
    m_home->setObjectName(QStringLiteral("remoteHome"));
    auto *parkRow = new QHBoxLayout;
    parkRow->addWidget(m_park);
    parkRow->addWidget(m_home);

    m_target = new QLineEdit;
    m_target->setObjectName(QStringLiteral("remoteTrackTarget"));
    m_target->setPlaceholderText(tr("satellite, sun, moon, azel:AZ,EL"));
    m_target->setMaxLength(remote::kLongestTrackTarget);
    m_track = new QPushButton(tr("Track"));
    m_track->setObjectName(QStringLiteral("remoteTrack"));
    m_untrack = new QPushButton(tr("Stop tracking"));
    m_untrack->setObjectName(QStringLiteral("remoteUntrack"));
    auto *trackRow = new QHBoxLayout;
    trackRow->addWidget(m_target, 1);
    trackRow->addWidget(m_track);
    trackRow->addWidget(m_untrack);

    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("remoteCommandMessage"));
    m_message->setTextFormat(Qt::PlainText);
    m_message->setWordWrap(true);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(gotoRow);
    layout->addLayout(jogGrid);
    layout->addLayout(parkRow);
    layout->addLayout(trackRow);
    layout->addWidget(m_message);

    connect(m_az, &QLineEdit::textChanged, this, &RemoteControls::revalidate);
    connect(m_el, &QLineEdit::textChanged, this, &RemoteControls::revalidate);
    connect(m_az, &QLineEdit::returnPressed, this, &RemoteControls::go);
    connect(m_el, &QLineEdit::returnPressed, this, &RemoteControls::go);
    connect(m_go, &QPushButton::clicked, this, &RemoteControls::go);
    connect(m_park, &QPushButton::clicked, this, [this] {
        if (m_station->park().isAccepted())
            showMessage(tr("park: sent"), false);
    });
    connect(m_home, &QPushButton::clicked, this, [this] {
        if (m_station->home().isAccepted())
            showMessage(tr("home: sent"), false);
    });
    connect(m_track, &QPushButton::clicked, this, [this] {
        if (m_target->text().trimmed().isEmpty()) {
            showMessage(tr("name a target to track"), true);
            return;
        }
        if (m_station->track(m_target->text(), 0).isAccepted())
            showMessage(tr("track %1: sent").arg(m_target->text().trimmed()), false);
    });
    connect(m_untrack, &QPushButton::clicked, this, [this] { m_station->untrack(); });
    connect(station, &RemoteStation::replied, this, [this](const QString &, const QString &command, bool ok, const QString &error) {
        if (command == u"jog" && ok)
            return;
        showMessage(ok ? tr("%1: accepted by the station").arg(command) : tr("%1 refused: %2").arg(command, error), !ok);
    });
    connect(station, &RemoteStation::commandFailed, this,
            [this](const QString &command, const QString &why) { showMessage(tr("%1: %2").arg(command, why), true); });
    connect(station, &RemoteStation::stateChanged, this, &RemoteControls::revalidate);
    revalidate();
}

QPushButton *RemoteControls::jogButton(const QString &text, const QString &name, double az, double el)
{
    auto *b = new QPushButton(text);
    b->setObjectName(name);
    b->setAutoRepeat(false);
    connect(b, &QPushButton::pressed, this, [this, az, el] {
        m_station->startJog(az * m_speed->value(), el * m_speed->value());
    });
    connect(b, &QPushButton::released, this, [this] { m_station->endJog({}); });
    m_jog << b;
    return b;
}

QString RemoteControls::message() const
{
    return m_message->text();
}

void RemoteControls::showMessage(const QString &text, bool problem)
{
    m_message->setText(text);
    m_message->setStyleSheet(problem ? warningText() : QString());
}

void RemoteControls::setFields(double az, double el)
{
    m_az->setText(QString::number(az, 'f', 1));
    m_el->setText(QString::number(el, 'f', 1));
}

void RemoteControls::revalidate()
{
    const auto az = fieldValue(m_az), el = fieldValue(m_el);
    bool ok = az && el && m_station->isLive();
    if (az && el) {
        const model::MoveCheck check = m_station->previewPointing(*az, *el);
        m_go->setToolTip(check.refusal);
        ok = ok && check.allowed();
    }
    m_go->setEnabled(ok);
}

bool RemoteControls::go()
{
    const auto az = fieldValue(m_az), el = fieldValue(m_el);
    if (!az || !el) {
        showMessage(tr("go to: azimuth and elevation are numbers of degrees"), true);
        return false;
    }
    if (const model::MoveCheck check = m_station->previewPointing(*az, *el); !check.allowed()) {
        showMessage(tr("go to: %1").arg(check.refusal), true);
        return false;
    }
    if (m_station->gotoPosition(*az, *el).isRefused())
        return false;
    showMessage(tr("go to az %1°, el %2°: sent").arg(*az, 0, 'f', 1).arg(*el, 0, 'f', 1), false);
    return true;
}

void RemoteControls::setLive(bool live)
{
    for (QWidget *w : std::initializer_list<QWidget *>{m_az, m_el, m_speed, m_park, m_home, m_target, m_track, m_untrack})
        w->setEnabled(live);
    for (QPushButton *b : std::as_const(m_jog))
        b->setEnabled(live);
    revalidate();
}

} // namespace slew::ui
