// SPDX-License-Identifier: GPL-3.0-or-later
#include "remote/stationnetworkwindow.h"

#include "stationwindow.h"
#include "remote/stationtile.h"

#include "remote/remotestation.h"
#include "remote/stationdirectory.h"

#include <QGridLayout>
#include <QGuiApplication>
#include <QLabel>
#include <QScreen>
#include <QScrollArea>
#include <QStatusBar>
#include <QVBoxLayout>

namespace slew::ui {

using remote::StationDirectory;


StationNetworkWindow::StationNetworkWindow(StationDirectory *directory, const remote::MqttSettings &settings, QWidget *parent)
    : QMainWindow(parent), m_directory(directory), m_settings(settings)
{
    setObjectName(QStringLiteral("stationNetworkWindow"));
    setWindowTitle(tr("Slew — REMOTE station network on %1").arg(directory->brokerDisplay()));
    m_header = new QLabel;
    m_header->setObjectName(QStringLiteral("networkBanner"));
    m_header->setTextFormat(Qt::PlainText);
    m_header->setMargin(6);
    m_header->setStyleSheet(QStringLiteral("#networkBanner{background:#1e4b7a;color:white;font-weight:bold;}"));
    auto *tiles = new QWidget;
    m_grid = new QGridLayout(tiles);
    m_grid->setSpacing(6);
    // Tiles keep their size and gather top left, however few there are.
    m_grid->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setWidget(tiles);
    auto *central = new QWidget;
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(6, 0, 6, 6);
    layout->addWidget(m_header);
    layout->addWidget(scroll, 1);
    setCentralWidget(central);

    connect(directory, &StationDirectory::stationAdded, this, &StationNetworkWindow::addTile);
    connect(directory, &StationDirectory::stationChanged, this, &StationNetworkWindow::refresh);
    connect(directory, &StationDirectory::connectionChanged, this, &StationNetworkWindow::refreshAll);
    connect(directory, &StationDirectory::messageRefused, this, [this](const QString &what) {
        statusBar()->showMessage(what, 30000);
    });
    // Ages grow between messages; a silent station greys.
    m_ages.setInterval(1000);
    connect(&m_ages, &QTimer::timeout, this, &StationNetworkWindow::refreshAll);
    m_ages.start();
    for (const QString &name : directory->names())
        addTile(name);
    refreshAll();
    const QScreen *screen = QGuiApplication::primaryScreen();
    resize(QSize(1440, 900).boundedTo(screen ? screen->availableSize() : QSize(1440, 900)));
}

void StationNetworkWindow::addTile(const QString &name)
{
    if (m_tiles.contains(name))
        return;
    auto *tile = new StationTile(name);
    connect(tile, &StationTile::openRequested, this, &StationNetworkWindow::openStation);
    m_tiles.insert(name, tile);
    m_columns = 0; // laid out again, in name order
    layOut();
    refresh(name);
}

void StationNetworkWindow::resizeEvent(QResizeEvent *event)
{
    QMainWindow::resizeEvent(event);
    layOut();
}

void StationNetworkWindow::layOut()
{
    const int columns = std::max(1, (width() - 36) / (StationTile::kWidth + m_grid->spacing()));
    if (columns == m_columns)
        return;
    m_columns = columns;
    int i = 0;
    for (const QString &n : m_directory->names()) {
        if (StationTile *t = m_tiles.value(n)) {
            m_grid->addWidget(t, i / columns, i % columns);
            ++i;
        }
    }
}

void StationNetworkWindow::refresh(const QString &name)
{
    StationTile *tile = m_tiles.value(name);
    const StationDirectory::Entry *e = m_directory->station(name);
    if (!tile || !e)
        return;
    tile->show(m_directory->isLive(name), e->online, e->state, e->sinceState.isValid() ? e->sinceState.elapsed() : -1);
    updateHeader();
}

void StationNetworkWindow::refreshAll()
{
    for (auto it = m_tiles.cbegin(); it != m_tiles.cend(); ++it)
        refresh(it.key());
    updateHeader();
}

void StationNetworkWindow::updateHeader()
{
    int live = 0;
    for (auto it = m_tiles.cbegin(); it != m_tiles.cend(); ++it)
        live += m_directory->isLive(it.key());
    const remote::MqttClient *client = m_directory->client();
    m_header->setText(client->isConnected()
                          ? tr("REMOTE: station network on %1 · %2, %3 live")
                                .arg(m_directory->brokerDisplay(),
                                     m_tiles.size() == 1 ? tr("1 station") : tr("%1 stations").arg(m_tiles.size()))
                                .arg(live)
                          : tr("REMOTE: station network on %1 · NOT CONNECTED: %2")
                                .arg(m_directory->brokerDisplay(),
                                     client->problem().isEmpty() ? tr("connecting") : client->problem()));
}

QWidget *StationNetworkWindow::openStation(const QString &name)
{
    auto *station = new remote::RemoteStation(m_settings, name);
    auto *window = new StationWindow(station);
    station->setParent(window);
    window->setAttribute(Qt::WA_DeleteOnClose);
    QString error;
    if (!station->open(&error)) {
        statusBar()->showMessage(tr("%1: %2").arg(name, error), 30000);
        delete window;
        return nullptr;
    }
    window->show();
    return window;
}

} // namespace slew::ui
