// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sky → Element sets…: where the element sets come from, and how old they
// are. The operator lists sources (CelesTrak-style group URLs, or local
// files as file:// URLs, one per line), refreshes them, and sees per source
// whether this refresh worked, how many sets it holds and how old the
// cached copy is; sets older than the age limit are named in a warning.
// Sources and limit are kept in the settings; the sets themselves live in
// core/sky's ElementSetSources, which the window owns and which works offline
// from its cache.

#include <QDialog>
#include <QList>
#include <QUrl>

class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;
class QPushButton;
class QTreeWidget;

namespace slew::sky {
class ElementSetSources;
}

namespace slew::ui {

class ElementSetsDialog : public QDialog {
    Q_OBJECT
public:
    ElementSetsDialog(sky::ElementSetSources *sources, QWidget *parent = nullptr);

    // The age limit the settings hold (the sources are in core/sky:
    // savedElementSetUrls(), shared with slew --update-elements).
    static double savedAgeLimitDays();

signals:
    // The operator changed the age limit (already saved).
    void ageLimitChanged(double days);

public:

    // Takes the typed sources (refusing a line that is not a URL, with its
    // number) and fetches them all; false, with the reason shown, if a line
    // is refused.
    bool refresh();
    void addFile(const QString &path);

private:
    void showStatus();
    bool readUrls(QList<QUrl> *urls, QString *error) const;

    sky::ElementSetSources *m_sources;
    QPlainTextEdit *m_urls = nullptr;
    QDoubleSpinBox *m_ageLimit = nullptr;
    QPushButton *m_refresh = nullptr;
    QTreeWidget *m_status = nullptr;
    QLabel *m_message = nullptr;
    QLabel *m_staleWarning = nullptr;
};

} // namespace slew::ui
