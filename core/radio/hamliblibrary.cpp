// SPDX-License-Identifier: GPL-3.0-or-later
#include "hamliblibrary.h"

#include <QObject>

#include <hamlib/rig.h>

#include <array>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace slew::radio {

namespace {

// Hamlib passes a message here instead of printing it; it goes nowhere.
// The level alone does not silence everything: a message logged at
// RIG_DEBUG_NONE passes a level of RIG_DEBUG_NONE.
int discardDebugMessage(enum rig_debug_level_e, rig_ptr_t, const char *, va_list)
{
    return 0;
}

std::array<QString, RIG_EEND> &errorWords()
{
    static std::array<QString, RIG_EEND> words;
    return words;
}

} // namespace

void prepareHamlib()
{
    static std::once_flag once;
    std::call_once(once, [] {
        rig_set_debug(RIG_DEBUG_NONE);
        rig_set_debug_callback(discardDebugMessage, nullptr);
        rig_load_all_backends();
        for (int code = 0; code < RIG_EEND; ++code)
            errorWords()[std::size_t(code)] = QString::fromLatin1(rigerror2(code)).trimmed();
    });
}

QString hamlibErrorWords(int code)
{
    prepareHamlib();
    const int index = std::abs(code);
    if (index >= RIG_EEND)
        return QObject::tr("Hamlib error %1").arg(code);
    return errorWords()[std::size_t(index)];
}

std::optional<HamlibModel> hamlibModel(int number)
{
    prepareHamlib();
    if (number <= 0)
        return std::nullopt;
    // rig_get_caps() only looks in the table; rig_check_backend() would
    // try to load a backend for an unknown number of a known family.
    const rig_caps *caps = rig_get_caps(rig_model_t(number));
    if (!caps)
        return std::nullopt;
    HamlibModel model;
    model.number = number;
    model.name = QStringLiteral("%1 %2").arg(QString::fromLatin1(caps->mfg_name), QString::fromLatin1(caps->model_name));
    model.serial = caps->port_type == RIG_PORT_SERIAL;
    for (const confparams *p = caps->cfgparams; p && p->token != RIG_CONF_END; ++p) {
        if (p->name && std::strcmp(p->name, "civaddr") == 0)
            model.hasCivAddress = true;
    }
    return model;
}

} // namespace slew::radio
