// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radiolinkbox.h"

#include "operatortheme.h"
#include "station/dopplerradio.h"

#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>

namespace slew::ui {

using radio::RadioLink;

namespace {

constexpr char kUriKey[] = "radio/uri";
constexpr char kRecentKey[] = "radio/recentUris";
constexpr char kConnectedKey[] = "radio/connected";
constexpr int kRecentKept = 6;

// What every station may pick from: the built-in simulated radio, Hamlib's
// rigctld where it listens by default, and the rotator controller's UP/DN.
QStringList usualUris()
{
    return {QStringLiteral("sim:"), QStringLiteral("rigctld://127.0.0.1:4532"),
            QString::fromLatin1(station::DopplerRadio::kControllerUri)};
}

} // namespace

RadioLinkBox::RadioLinkBox(station::DopplerRadio *radio, QWidget *parent) : QWidget(parent), m_radio(radio)
{
    setObjectName(QStringLiteral("radioLinkBox"));
    m_uri = new QComboBox;
    m_uri->setObjectName(QStringLiteral("radioUri"));
    m_uri->setEditable(true);
    m_uri->setInsertPolicy(QComboBox::NoInsert);
    m_uri->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_uri->setMinimumContentsLength(16);
    m_uri->setToolTip(tr("sim: the built-in simulated radio; rigctld://host:port a running rigctld "
                         "(rigctld -m MODEL -r DEVICE); controller: the rotator controller's own radio (UP/DN)"));
    m_connect = new QPushButton(tr("Connect"));
    m_connect->setObjectName(QStringLiteral("radioConnect"));
    m_connect->setAutoDefault(false);
    m_disconnect = new QPushButton(tr("Disconnect"));
    m_disconnect->setObjectName(QStringLiteral("radioDisconnect"));
    m_disconnect->setAutoDefault(false);
    m_state = new QLabel;
    m_state->setObjectName(QStringLiteral("radioLinkState"));
    m_state->setWordWrap(true);
    m_refusal = new QLabel;
    m_refusal->setObjectName(QStringLiteral("radioLinkRefusal"));
    m_refusal->setWordWrap(true);
    m_refusal->setStyleSheet(refusedText());
    m_refusal->hide();

    auto *grid = new QGridLayout(this);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setVerticalSpacing(3);
    grid->addWidget(m_uri, 0, 0);
    grid->addWidget(m_connect, 0, 1);
    grid->addWidget(m_disconnect, 0, 2);
    grid->addWidget(m_refusal, 1, 0, 1, 3);
    grid->addWidget(m_state, 2, 0, 1, 3);
    grid->setColumnStretch(0, 1);

    connect(m_connect, &QPushButton::clicked, this, &RadioLinkBox::onConnectClicked);
    connect(m_uri->lineEdit(), &QLineEdit::returnPressed, this, &RadioLinkBox::onConnectClicked);
    connect(m_disconnect, &QPushButton::clicked, this, &RadioLinkBox::disconnectRadio);
    connect(m_radio, &station::DopplerRadio::linkStateChanged, this, &RadioLinkBox::showState);
    connect(m_radio, &station::DopplerRadio::reopenScheduled, this, &RadioLinkBox::showReopen);

    const QSettings settings;
    const QString kept = settings.value(QLatin1String(kUriKey)).toString();
    fillList(kept.isEmpty() ? m_radio->linkUri() : kept);
    m_stateText = tr("Not connected");
    m_state->setText(m_stateText);
    showButtons();
    // A radio left connected is connected again, as a server left on is on
    // again: it tunes nothing until a pass of a satellite it has frequencies for.
    if (!kept.isEmpty() && settings.value(QLatin1String(kConnectedKey)).toBool())
        connectTo(kept);
}

QStringList RadioLinkBox::offeredUris() const
{
    QStringList uris;
    for (int i = 0; i < m_uri->count(); ++i)
        uris << m_uri->itemText(i);
    return uris;
}

void RadioLinkBox::fillList(const QString &current)
{
    QStringList uris = QSettings().value(QLatin1String(kRecentKey)).toStringList();
    for (const QString &usual : usualUris())
        if (!uris.contains(usual))
            uris << usual;
    m_uri->clear();
    m_uri->addItems(uris);
    m_uri->setCurrentText(current.isEmpty() ? usualUris().value(1) : current);
}

void RadioLinkBox::remember(const QString &uri)
{
    QSettings settings;
    QStringList recent = settings.value(QLatin1String(kRecentKey)).toStringList();
    recent.removeAll(uri);
    recent.prepend(uri);
    while (recent.size() > kRecentKept)
        recent.removeLast();
    settings.setValue(QLatin1String(kRecentKey), recent);
    settings.setValue(QLatin1String(kUriKey), uri);
    fillList(uri);
}

void RadioLinkBox::onConnectClicked()
{
    connectTo(m_uri->currentText());
}

bool RadioLinkBox::connectTo(const QString &text)
{
    const QString uri = text.trimmed();
    m_uri->setCurrentText(uri);
    if (uri.isEmpty()) {
        m_refusal->setText(tr("Name a radio: sim:, rigctld://host:port or controller"));
        m_refusal->show();
        return false;
    }
    // The same radio again is connected as it is: a new link would close
    // the open one and lose what it measured.
    if (uri != m_radio->linkUri() || !m_radio->link()) {
        QString why;
        if (!m_radio->setLink(uri, &why)) {
            m_refusal->setText(why);
            m_refusal->show();
            emit message(tr("radio: %1").arg(why));
            return false;
        }
    }
    m_refusal->hide();
    m_refusal->clear();
    remember(uri);
    QSettings().setValue(QLatin1String(kConnectedKey), true);
    m_radio->connectRadio();
    showButtons();
    return true;
}

void RadioLinkBox::disconnectRadio()
{
    m_radio->disconnectRadio();
    QSettings().setValue(QLatin1String(kConnectedKey), false);
    m_refusal->hide();
    // A link already lost says nothing more as it is let go: the retries
    // it was waiting for are over all the same.
    if (!m_radio->link() || m_radio->link()->state() == RadioLink::State::Closed)
        showState(RadioLink::State::Closed, QString());
    showButtons();
}

void RadioLinkBox::showButtons()
{
    m_disconnect->setEnabled(m_radio->isWanted());
}

void RadioLinkBox::showState(RadioLink::State state, const QString &detail)
{
    switch (state) {
    case RadioLink::State::Open: m_stateText = tr("Open: %1").arg(detail); break;
    case RadioLink::State::Opening:
        m_stateText = m_radio->reopenAttempts() > 0
                          ? tr("Opening again (attempt %1): %2").arg(m_radio->reopenAttempts()).arg(detail)
                          : tr("Opening: %1").arg(detail);
        break;
    case RadioLink::State::Closed:
        m_stateText = m_radio->isWanted() ? tr("Lost: %1").arg(detail) : tr("Not connected");
        break;
    }
    m_state->setText(m_stateText);
    m_state->setStyleSheet(state == RadioLink::State::Closed && m_radio->isWanted() ? warningText()
                                                                                     : QString());
    showButtons();
}

void RadioLinkBox::showReopen(int attempt, int seconds)
{
    m_state->setText(
        tr("%1 — trying again in %n s (attempt %2)", nullptr, seconds).arg(m_stateText, QString::number(attempt)));
}

} // namespace slew::ui
