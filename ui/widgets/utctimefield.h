// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A UTC instant as the operator types or pastes it: "2026-12-05 15:24:00",
// "2026-12-05T15:24:00Z", "2026-12-05 15:24", or the Time controller's own
// "… UTC". A line of text rather than a QDateTimeEdit: that one types into
// one section at a time, and a ':' typed after a full hour skips the minutes
// ("2026-12-05 15:24:00" became 15:59:24). What is read is the whole text,
// by the one ISO 8601 reader the command line's --clock-start uses too.

#include <QLineEdit>

#include <optional>

namespace slew::ui {

class UtcTimeField : public QLineEdit {
    Q_OBJECT
public:
    explicit UtcTimeField(QWidget *parent = nullptr);

    // Shows `julian` as "2026-12-05 15:24:00".
    void setJulian(double julian);
    // The instant typed, or nothing and `why` in the operator's words.
    std::optional<double> julian(QString *why) const;
};

} // namespace slew::ui
