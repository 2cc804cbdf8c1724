#include "presets.h"

#include "movegate.h"

#include <QJsonObject>
#include <QObject>

#include <cmath>

namespace slew::model {

const Preset *PresetList::at(int index) const
{
    return index >= 0 && index < size() ? &m_presets[index] : nullptr;
}

QString PresetList::store(const Preset &preset, const RotatorLimits &limits)
{
    Preset p = preset;
    p.name = p.name.simplified();
    if (p.name.isEmpty())
        return QObject::tr("a preset needs a name");
    if (p.name.size() > 40)
        return QObject::tr("a preset name is at most 40 characters");
    if (!std::isfinite(p.azimuth) || !std::isfinite(p.elevation))
        return QObject::tr("preset '%1' has no position").arg(p.name);
    if (QString e = MoveGate(limits).pointing(p.azimuth, p.elevation, std::nullopt).refusal; !e.isEmpty())
        return e;
    for (Preset &existing : m_presets) {
        if (existing.name.compare(p.name, Qt::CaseInsensitive) == 0) {
            existing = p;
            return {};
        }
    }
    if (size() >= kMaxPresets)
        return QObject::tr("all %1 presets are in use; remove one first").arg(kMaxPresets);
    m_presets.append(p);
    return {};
}

QString PresetList::remove(int index)
{
    if (!at(index))
        return QObject::tr("there is no preset %1").arg(index + 1);
    m_presets.removeAt(index);
    return {};
}

QJsonArray PresetList::toJson() const
{
    QJsonArray out;
    for (const Preset &p : m_presets)
        out.append(QJsonObject{{"name", p.name}, {"az", p.azimuth}, {"el", p.elevation}});
    return out;
}

std::optional<PresetList> PresetList::fromJson(const QJsonArray &json, QString *error)
{
    PresetList list;
    for (const QJsonValue &v : json) {
        const QJsonObject o = v.toObject();
        const QString name = o.value("name").toString().simplified();
        // JSON's 1e999 reads as infinity: finite numbers only.
        if (!v.isObject() || name.isEmpty() || !o.value("az").isDouble() || !o.value("el").isDouble()
            || !std::isfinite(o.value("az").toDouble()) || !std::isfinite(o.value("el").toDouble())) {
            if (error)
                *error = QObject::tr("a preset needs a name, and az and el as finite numbers");
            return std::nullopt;
        }
        if (list.size() >= kMaxPresets)
            break;
        list.m_presets.append(Preset{name, o.value("az").toDouble(), o.value("el").toDouble()});
    }
    return list;
}

} // namespace slew::model
