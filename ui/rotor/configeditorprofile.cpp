// ConfigEditor's profile import and export: a profile file carries the
// limits, park position, gains and link settings of one rotator.

#include "rotor/configeditor.h"

#include "input/finitenumber.h"

#include "model/rotatorprofile.h"

#include <QLineEdit>

namespace slew::ui {

bool ConfigEditor::exportProfile(const QString &path, QString *error) const
{
    model::RotatorProfile profile = m_session->profile();
    auto number = [this](int reg) -> std::optional<double> {
        // The device's text: a finite number, or nothing for the profile.
        return input::finiteNumber(deviceValue(reg));
    };
    // What the device holds now is what the profile should remember.
    for (auto [first, gains] : {std::pair{1, &profile.azGains}, std::pair{4, &profile.elGains}}) {
        const auto p = number(first), i = number(first + 1), d = number(first + 2);
        if (p && i && d)
            *gains = model::PidGains{*p, *i, *d};
    }
    if (const auto az = number(7))
        profile.parkAz = *az;
    if (const auto el = number(8))
        profile.parkEl = *el;
    return profile.save(path, error);
}

bool ConfigEditor::importProfile(const QString &path, QString *error)
{
    auto loaded = model::RotatorProfile::load(path, error);
    if (!loaded)
        return false;
    if (const QString why = loaded->validate(); !why.isEmpty()) {
        if (error)
            *error = tr("%1: %2").arg(path, why);
        return false;
    }
    model::RotatorProfile profile = *loaded;
    if (m_session->state() != session::RotatorSession::State::Disconnected) {
        // The link in use stays as it is; the file's link settings apply on the next connection.
        profile.uri = m_session->profile().uri;
        profile.dialect = m_session->profile().dialect;
    }
    m_session->setProfile(profile);

    // Gains and park go to the device only through Apply, after the operator sees them.
    auto propose = [this](int reg, double value) {
        Row &row = rowFor(reg);
        if (!row.edit)
            return;
        row.edit->setText(QString::number(value, 'g', 8));
        onEdited(reg);
    };
    for (auto [first, gains] : {std::pair{1, profile.azGains}, std::pair{4, profile.elGains}}) {
        if (!gains)
            continue;
        propose(first, gains->kp);
        propose(first + 1, gains->ki);
        propose(first + 2, gains->kd);
    }
    propose(7, profile.parkAz);
    propose(8, profile.parkEl);
    say(tr("Profile '%1' loaded; changed registers are marked, Apply writes them.").arg(profile.name), false);
    emit profileChanged();
    return true;
}

} // namespace slew::ui
