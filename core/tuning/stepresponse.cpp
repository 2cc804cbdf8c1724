#include "stepresponse.h"

namespace slew::tuning {

QString formatSeconds(double seconds, bool reached)
{
    if (!reached)
        return QStringLiteral("—");
    return QStringLiteral("%1 s").arg(seconds, 0, 'f', 2);
}

} // namespace slew::tuning
