// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/targetpicker.h"

#include "tracking/tracktarget.h"

#include "sky/elementsetsources.h"

#include <QAction>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QSettings>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace slew::ui {

using sky::FavouriteTarget;

namespace {

constexpr int kMostTargetsListed = 300; // a full catalogue is searched, not scrolled

// What a row of the list is, beside its text.
enum TargetRole { NumberRole = Qt::UserRole, KindRole, NameRole, MissingRole };

FavouriteTarget targetOf(const QListWidgetItem *item)
{
    return {FavouriteTarget::Kind(item->data(KindRole).toInt()), item->data(NumberRole).toInt(),
            item->data(NameRole).toString()};
}

QString displayName(const FavouriteTarget &t)
{
    switch (t.kind) {
    case FavouriteTarget::Kind::Sun: return QObject::tr("Sun");
    case FavouriteTarget::Kind::Moon: return QObject::tr("Moon");
    case FavouriteTarget::Kind::Direction: return t.name;
    case FavouriteTarget::Kind::Satellite: break;
    }
    return t.name.isEmpty() ? QString::number(t.catalogueNumber) : t.name;
}

bool matches(const FavouriteTarget &t, const QString &wanted)
{
    if (wanted.isEmpty())
        return true;
    if (t.kind != FavouriteTarget::Kind::Satellite)
        return displayName(t).startsWith(wanted, Qt::CaseInsensitive);
    // A favourite satellite is found as the loaded sets are ("AO-91" for
    // "FOX-1B (AO-91)"): the same search, on the one name.
    sky::ElementSet named;
    named.name = t.name;
    named.catalogueNumber = t.catalogueNumber;
    return !sky::findSatellites({named}, wanted).isEmpty();
}

} // namespace

TargetPicker::TargetPicker(const sky::ElementSetSources *sets, QWidget *parent) : QWidget(parent), m_sets(sets)
{
    setObjectName(QStringLiteral("targetPicker"));
    m_search = new QLineEdit;
    m_search->setObjectName(QStringLiteral("targetSearch"));
    // Short enough for a 1280-pixel screen; the tooltip has every form.
    m_search->setPlaceholderText(tr("satellite, sun, moon, azel:…, radec:…"));
    // What it takes, readable however narrow the window: the page scrolls instead.
    m_search->setMinimumWidth(m_search->fontMetrics().horizontalAdvance(m_search->placeholderText()) + 24);
    m_search->setToolTip(tr("A satellite's name or catalogue number, sun, moon, a fixed direction "
                            "(azel:AZ,EL) or a radio source (radec:RA,DEC)"));
    m_favourite = new QToolButton;
    m_favourite->setObjectName(QStringLiteral("favouriteToggle"));
    m_favourite->setCheckable(true);
    m_favourite->setShortcut(QKeySequence(tr("Ctrl+D")));
    m_favouritesOnly = new QToolButton;
    m_favouritesOnly->setObjectName(QStringLiteral("favouritesOnly"));
    m_favouritesOnly->setCheckable(true);
    m_favouritesOnly->setText(tr("★ Favourites"));
    m_favouritesOnly->setToolTip(tr("List only the favourites"));
    m_list = new QListWidget;
    m_list->setObjectName(QStringLiteral("targets"));
    m_list->setContextMenuPolicy(Qt::CustomContextMenu);
    m_favourites.load(QSettings());

    auto *searchRow = new QHBoxLayout;
    searchRow->addWidget(new QLabel(tr("Target")));
    searchRow->addWidget(m_search, 1);
    searchRow->addWidget(m_favourite);
    searchRow->addWidget(m_favouritesOnly);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(searchRow);
    layout->addWidget(m_list, 1);

    connect(m_search, &QLineEdit::textChanged, this, &TargetPicker::fill);
    connect(m_favouritesOnly, &QToolButton::toggled, this, &TargetPicker::fill);
    connect(m_list, &QListWidget::currentRowChanged, this, [this] {
        showFavouriteButton();
        emit chosenChanged();
    });
    connect(m_favourite, &QToolButton::clicked, this, [this] {
        if (const auto target = chosen())
            toggleFavourite(*target);
    });
    connect(m_list, &QListWidget::customContextMenuRequested, this, &TargetPicker::showMenu);
    connect(m_sets, &sky::ElementSetSources::setsChanged, this, &TargetPicker::fill);
    fill();
}

bool TargetPicker::selectTarget(const QString &name)
{
    m_search->setText(name);
    if (m_list->count() == 0)
        return false;
    m_list->setCurrentRow(0);
    return true;
}

std::optional<FavouriteTarget> TargetPicker::chosen() const
{
    const QListWidgetItem *item = m_list->currentItem();
    return item ? std::optional(targetOf(item)) : std::nullopt;
}

bool TargetPicker::chosenIsMissing() const
{
    const QListWidgetItem *item = m_list->currentItem();
    return item && item->data(MissingRole).toBool();
}

void TargetPicker::fill()
{
    const QString wanted = m_search->text().trimmed();
    const QList<sky::ElementSet> sets = m_sets->sets();
    const std::optional<FavouriteTarget> current = chosen();
    if (m_favourites.renameFrom(sets)) {
        QSettings settings;
        m_favourites.save(settings);
    }
    const QSignalBlocker quiet(m_list); // one change told at the end, not one per row
    m_list->clear();
    // The favourites first, those no loaded set holds among them: a source
    // dropped or a reload that lacks one must not make it vanish unseen.
    const QList<FavouriteTarget> missing = m_favourites.missingFrom(sets);
    for (const FavouriteTarget &f : m_favourites.list()) {
        const bool gone = std::any_of(missing.begin(), missing.end(), [&](const auto &m) { return m.sameTarget(f); });
        if (matches(f, wanted))
            addItem(f, true, gone);
    }
    // A direction typed in full (azel:AZ,EL or radec:RA,DEC) is a target of its own.
    QString badDirection;
    if (tracking::TrackTarget::parseFixedOrCelestial(wanted, &badDirection)) {
        const FavouriteTarget typed = FavouriteTarget::direction(wanted);
        if (!m_favourites.contains(typed))
            addItem(typed, false, false);
    }
    if (!m_favouritesOnly->isChecked()) {
        for (const FavouriteTarget &body : {FavouriteTarget::sun(), FavouriteTarget::moon()}) {
            if (!m_favourites.contains(body) && matches(body, wanted))
                addItem(body, false, false);
        }
        QList<const sky::ElementSet *> shown;
        if (wanted.isEmpty()) {
            for (const sky::ElementSet &t : sets)
                shown.append(&t);
        } else {
            shown = sky::findSatellites(sets, wanted);
        }
        for (const sky::ElementSet *t : shown.mid(0, kMostTargetsListed)) {
            const FavouriteTarget target = FavouriteTarget::satellite(*t);
            if (!m_favourites.contains(target))
                addItem(target, false, false);
        }
    }
    for (int row = 0; current && row < m_list->count(); ++row) {
        if (targetOf(m_list->item(row)).sameTarget(*current)) {
            m_list->setCurrentRow(row);
            break;
        }
    }
    showFavouriteButton();
    // Told even when the same target stays chosen: a reload may bring newer elements.
    emit chosenChanged();
}

void TargetPicker::addItem(const FavouriteTarget &target, bool favourite, bool missing)
{
    QString text = displayName(target);
    if (missing)
        text = tr("%1 (%2): not in the loaded element sets").arg(text).arg(target.catalogueNumber);
    auto *item = new QListWidgetItem(favourite ? QStringLiteral("★ ") + text : text);
    item->setData(NumberRole, target.catalogueNumber);
    item->setData(KindRole, int(target.kind));
    item->setData(NameRole, target.name);
    item->setData(MissingRole, missing);
    if (missing) {
        item->setForeground(palette().color(QPalette::Disabled, QPalette::Text));
        QFont italic = item->font();
        italic.setItalic(true);
        item->setFont(italic);
        item->setToolTip(tr("No loaded element set holds this favourite: add the source that has it in "
                            "Sky → Element sets…, or remove it from the favourites."));
    }
    m_list->addItem(item);
}

void TargetPicker::toggleFavourite(const FavouriteTarget &target)
{
    m_favourites.toggle(target);
    QSettings settings;
    m_favourites.save(settings);
    fill();
    emit favouritesChanged();
}

void TargetPicker::showMenu(const QPoint &at)
{
    const QListWidgetItem *item = m_list->itemAt(at);
    if (!item)
        return;
    // popup(), not exec(): no nested event loop under a running tracker.
    auto *menu = new QMenu(this);
    menu->setAttribute(Qt::WA_DeleteOnClose);
    const FavouriteTarget target = targetOf(item);
    QAction *toggle = menu->addAction(m_favourites.contains(target) ? tr("Remove from favourites") : tr("Add to favourites"));
    connect(toggle, &QAction::triggered, this, [this, target] { toggleFavourite(target); });
    menu->popup(m_list->viewport()->mapToGlobal(at));
}

void TargetPicker::showFavouriteButton()
{
    const auto target = chosen();
    const bool marked = target && m_favourites.contains(*target);
    m_favourite->setEnabled(target.has_value());
    m_favourite->setChecked(marked);
    m_favourite->setText(marked ? QStringLiteral("★") : QStringLiteral("☆"));
    m_favourite->setToolTip(marked ? tr("Remove the chosen target from the favourites (Ctrl+D)")
                                   : tr("Add the chosen target to the favourites (Ctrl+D)"));
}

} // namespace slew::ui
