// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The station's transponder sources, kept by the operator from the Radio
// tab: Gpredict .trsp files, SatNOGS DB lists (.json) and URLs, added and
// removed here and kept in the settings under the same key
// `slew --update-transponders` keeps them (radio/transpondersources.h), so
// both read one list. A source added is fetched at once with the others; a
// source removed is gone from the list the radio's transponders come from.
// What is typed and refused says why under the field and changes nothing.
// Not modal: the window's Stop stays within reach.

#include <QDialog>

class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;

namespace slew::radio {
class TransponderSources;
}

namespace slew::ui {

class RadioTransponderDialog : public QDialog {
    Q_OBJECT
public:
    // The sources must outlive the dialog.
    explicit RadioTransponderDialog(radio::TransponderSources *sources, QWidget *parent = nullptr);

    // Adds what the field holds, as Add does: false, with the refusal
    // shown and the list unchanged, when it is no source.
    bool addSource();
    // Removes the source selected, as Remove does.
    void removeSource();

signals:
    void message(const QString &text); // for the event log

private:
    void showSources();
    void keep(const QList<QUrl> &urls);

    radio::TransponderSources *m_sources;
    QListWidget *m_list;
    QLineEdit *m_field;
    QLabel *m_refusal;
    QPushButton *m_remove;
};

} // namespace slew::ui
