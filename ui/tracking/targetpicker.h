// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Tracking tab's choice of target: a search by name or number over the
// loaded element sets, the sun and the moon, with the operator's favourites
// at the head of the list. The star (or Ctrl+D, or the list's context menu)
// marks or unmarks the chosen target; "★ Favourites" lists only them. A
// favourite satellite no loaded set holds stays listed, greyed, as missing.
// The favourites are kept in the settings (core/sky/favouritetargets.h).

#include "sky/favouritetargets.h"

#include <QWidget>

#include <optional>

class QLineEdit;
class QListWidget;
class QListWidgetItem;
class QToolButton;

namespace slew::sky {
class ElementSetSources;
}

namespace slew::ui {

class TargetPicker : public QWidget {
    Q_OBJECT
public:
    explicit TargetPicker(const sky::ElementSetSources *sets, QWidget *parent = nullptr);

    // Searches for `name` and chooses the first target found.
    bool selectTarget(const QString &name);
    // The chosen target, with a satellite's catalogue number; none chosen, none.
    std::optional<sky::FavouriteTarget> chosen() const;
    // The chosen target is a favourite that no loaded set holds.
    bool chosenIsMissing() const;

    QListWidget *list() const { return m_list; }
    QToolButton *favouriteButton() const { return m_favourite; }
    QToolButton *favouritesOnlyButton() const { return m_favouritesOnly; }

signals:
    // Another target, or the same one with elements reloaded.
    void chosenChanged();
    // A target was marked or unmarked (saved in the settings already).
    void favouritesChanged();

private:
    void fill();
    void addItem(const sky::FavouriteTarget &target, bool favourite, bool missing);
    void toggleFavourite(const sky::FavouriteTarget &target);
    void showFavouriteButton();
    void showMenu(const QPoint &at);

    const sky::ElementSetSources *m_sets;
    sky::FavouriteTargets m_favourites;
    QLineEdit *m_search;
    QToolButton *m_favourite;
    QToolButton *m_favouritesOnly;
    QListWidget *m_list;
};

} // namespace slew::ui
