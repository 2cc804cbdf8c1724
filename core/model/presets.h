#pragma once
// Named az/el positions the operator returns to (the Micro-2g program's presets, with
// names and elevation): stored from the current position, recalled with one
// click or a number key 1..9.

#include <QJsonArray>
#include <QList>
#include <QString>

#include <optional>

namespace slew::model {

struct RotatorLimits;

struct Preset {
    QString name;
    double azimuth = 0.0;
    double elevation = 0.0;
    friend bool operator==(const Preset &, const Preset &) = default;
};

class PresetList {
public:
    static constexpr int kMaxPresets = 9; // one per number key

    const QList<Preset> &presets() const { return m_presets; }
    int size() const { return int(m_presets.size()); }
    const Preset *at(int index) const;

    // Each returns an empty string on success, else why nothing changed.
    // A preset with an existing name replaces it; names are trimmed.
    QString store(const Preset &preset, const RotatorLimits &limits);
    QString remove(int index);

    QJsonArray toJson() const;
    // Reads what toJson() wrote; a malformed entry gives an error and no list.
    static std::optional<PresetList> fromJson(const QJsonArray &json, QString *error);

private:
    QList<Preset> m_presets;
};

} // namespace slew::model
