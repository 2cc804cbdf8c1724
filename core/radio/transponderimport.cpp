// SPDX-License-Identifier: GPL-3.0-or-later
#include "transponderimport.h"

#include "input/boundedfile.h"
#include "input/finitenumber.h"
#include "input/logtext.h"

#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <QRegularExpression>

#include <cmath>
#include <limits>

namespace slew::radio {
namespace {

// Text from the file, as a message shows it: escaped, and short.
QString shown(const QString &text, int maxChars = 40)
{
    return input::loggableText(text, maxChars);
}

QString quoted(const QString &text)
{
    return QLatin1Char('\'') + shown(text) + QLatin1Char('\'');
}

// A number from the file as a message shows it: whole hertz in full.
QString number(double x)
{
    return QString::number(x, 'g', 15);
}

// Collects what one source yields, keeping the first kMostSkipMessages
// messages and counting the rest.
struct Collector {
    QString source; // escaped, ready for messages
    TransponderImport result;

    void skip(const QString &where, const QString &why)
    {
        ++result.skippedCount;
        if (result.skipped.size() < kMostSkipMessages)
            result.skipped.append(QStringLiteral("%1: %2: %3").arg(source, where, why));
    }

    // The source refused whole: nothing from it is kept, the messages are.
    TransponderImport refuse(const QString &why)
    {
        result.transponders.clear();
        result.error = QStringLiteral("%1: %2").arg(source, why);
        return result;
    }

    // Nothing usable is a refusal too, saying why.
    TransponderImport finish(int entries, const char *kind)
    {
        if (!result.transponders.isEmpty())
            return result;
        if (entries == 0)
            return refuse(QStringLiteral("no %1 in it").arg(QString::fromLatin1(kind)));
        return refuse(QStringLiteral("no usable transponder: all %1 %2 were skipped").arg(entries).arg(QString::fromLatin1(kind)));
    }
};

// A file's bytes without a leading UTF-8 byte-order mark, which some
// editors write.
QByteArray withoutByteOrderMark(const QByteArray &bytes)
{
    return bytes.startsWith("\xEF\xBB\xBF") ? bytes.sliced(3) : bytes;
}

// One frequency as read: none (absent, null, or 0, which Gpredict writes
// for none), or a finite number of hertz above 0 and at most
// kHighestFrequencyHz. *why says what is wrong, after the field's name.
bool checkFrequency(double hz, std::optional<double> *out, QString *why)
{
    if (!std::isfinite(hz)) {
        *why = QStringLiteral("%1 is not a finite number").arg(number(hz));
        return false;
    }
    if (hz < 0) {
        *why = QStringLiteral("%1 Hz is negative").arg(number(hz));
        return false;
    }
    if (hz > kHighestFrequencyHz) {
        *why = QStringLiteral("%1 Hz is above 300 GHz, the top of the radio spectrum").arg(number(hz));
        return false;
    }
    *out = hz > 0 ? std::optional<double>(hz) : std::nullopt;
    return true;
}

// A number written as text, through the input rule: "'abc' is not a
// number", "'nan' is not a finite number".
std::optional<double> numberInText(const QString &text, QString *why)
{
    static constexpr input::NumberRange anyFinite{-std::numeric_limits<double>::max(),
                                                  std::numeric_limits<double>::max(), ""};
    return input::numberIn(text, anyFinite, why);
}

bool frequencyFromText(const QString &text, std::optional<double> *out, QString *why)
{
    const std::optional<double> hz = numberInText(text, why);
    return hz && checkFrequency(*hz, out, why);
}

// The four frequencies, made consistent as Gpredict makes them: a high
// edge alone is the single frequency; a low above its high is refused.
struct Frequencies {
    std::optional<double> uplinkLow, uplinkHigh, downlinkLow, downlinkHigh;
};

bool orderEdges(std::optional<double> *low, std::optional<double> *high, const QString &lowName,
                const QString &highName, QString *why)
{
    if (!*low && *high) {
        *low = *high;
        *high = std::nullopt;
    }
    if (*low && *high && **low > **high) {
        *why = QStringLiteral("%1 %2 Hz is above %3 %4 Hz").arg(lowName, number(**low), highName, number(**high));
        return false;
    }
    return true;
}

bool finishFrequencies(Frequencies *f, const QStringList &names, Transponder *out, QString *why)
{
    if (!orderEdges(&f->uplinkLow, &f->uplinkHigh, names[0], names[1], why)
        || !orderEdges(&f->downlinkLow, &f->downlinkHigh, names[2], names[3], why))
        return false;
    if (!f->uplinkLow && !f->downlinkLow) {
        *why = QStringLiteral("no uplink or downlink frequency");
        return false;
    }
    out->uplinkLowHz = f->uplinkLow;
    out->uplinkHighHz = f->uplinkHigh;
    out->downlinkLowHz = f->downlinkLow;
    out->downlinkHighHz = f->downlinkHigh;
    return true;
}

// ---- SatNOGS DB --------------------------------------------------------

const QStringList kSatnogsFrequencyKeys{QStringLiteral("uplink_low"), QStringLiteral("uplink_high"),
                                        QStringLiteral("downlink_low"), QStringLiteral("downlink_high")};

QString jsonKind(const QJsonValue &v)
{
    switch (v.type()) {
    case QJsonValue::Bool:
        return v.toBool() ? QStringLiteral("true") : QStringLiteral("false");
    case QJsonValue::Double:
        return QStringLiteral("a number");
    case QJsonValue::String:
        return QStringLiteral("text");
    case QJsonValue::Array:
        return QStringLiteral("an array");
    case QJsonValue::Object:
        return QStringLiteral("an object");
    default:
        return QStringLiteral("null");
    }
}

bool isAbsent(const QJsonValue &v)
{
    return v.isUndefined() || v.isNull();
}

// A frequency field: a number, or text holding one (read by the input
// rule), or null.
bool jsonFrequency(const QJsonObject &entry, const QString &key, std::optional<double> *out, QString *why)
{
    const QJsonValue v = entry.value(key);
    QString reason;
    bool ok = false;
    if (isAbsent(v)) {
        *out = std::nullopt;
        return true;
    }
    if (v.isDouble())
        ok = checkFrequency(v.toDouble(), out, &reason);
    else if (v.isString())
        ok = frequencyFromText(v.toString(), out, &reason);
    else
        reason = QStringLiteral("is %1, not a number").arg(jsonKind(v));
    if (!ok)
        *why = key + QLatin1Char(' ') + reason;
    return ok;
}

bool jsonBool(const QJsonObject &entry, const QString &key, std::optional<bool> *out, QString *why)
{
    const QJsonValue v = entry.value(key);
    if (isAbsent(v)) {
        *out = std::nullopt;
        return true;
    }
    if (!v.isBool()) {
        *why = QStringLiteral("%1 is %2, not true or false").arg(key, v.isString() ? quoted(v.toString()) : jsonKind(v));
        return false;
    }
    *out = v.toBool();
    return true;
}

bool jsonText(const QJsonObject &entry, const QString &key, QString *out, QString *why)
{
    const QJsonValue v = entry.value(key);
    if (isAbsent(v)) {
        out->clear();
        return true;
    }
    if (!v.isString()) {
        *why = QStringLiteral("%1 is %2, not text").arg(key, jsonKind(v));
        return false;
    }
    *out = v.toString();
    return true;
}

bool jsonNoradId(const QJsonObject &entry, int *out, QString *why)
{
    const QString key = QStringLiteral("norad_cat_id");
    const QJsonValue v = entry.value(key);
    if (isAbsent(v)) {
        *why = QStringLiteral("no norad_cat_id: the satellite has no catalogue number");
        return false;
    }
    QString reason;
    std::optional<int> id;
    if (v.isDouble()) {
        const double x = v.toDouble();
        if (std::isfinite(x) && x == std::floor(x) && x >= 1 && x <= kLargestNoradId)
            id = int(x);
        else
            reason = QStringLiteral("%1 is not a catalogue number (1..%2)").arg(number(x)).arg(kLargestNoradId);
    } else if (v.isString()) {
        id = input::wholeNumberIn(v.toString(), 1, kLargestNoradId, &reason);
    } else {
        reason = QStringLiteral("is %1, not a number").arg(jsonKind(v));
    }
    if (!id) {
        *why = key + QLatin1Char(' ') + reason;
        return false;
    }
    *out = *id;
    return true;
}

// One element of the array, or why it is skipped.
bool readSatnogsEntry(const QJsonValue &value, Transponder *out, QString *why)
{
    if (!value.isObject()) {
        *why = QStringLiteral("is %1, not a transmitter object").arg(jsonKind(value));
        return false;
    }
    const QJsonObject entry = value.toObject();
    Transponder t;
    Frequencies f;
    std::optional<bool> invert, alive;
    QString status;
    if (!jsonNoradId(entry, &t.noradId, why) || !jsonText(entry, QStringLiteral("description"), &t.description, why)
        || !jsonText(entry, QStringLiteral("uuid"), &t.uuid, why) || !jsonText(entry, QStringLiteral("mode"), &t.mode, why)
        || !jsonFrequency(entry, kSatnogsFrequencyKeys[0], &f.uplinkLow, why)
        || !jsonFrequency(entry, kSatnogsFrequencyKeys[1], &f.uplinkHigh, why)
        || !jsonFrequency(entry, kSatnogsFrequencyKeys[2], &f.downlinkLow, why)
        || !jsonFrequency(entry, kSatnogsFrequencyKeys[3], &f.downlinkHigh, why)
        || !jsonBool(entry, QStringLiteral("invert"), &invert, why)
        || !jsonBool(entry, QStringLiteral("alive"), &alive, why)
        || !jsonText(entry, QStringLiteral("status"), &status, why))
        return false;
    if (!finishFrequencies(&f, kSatnogsFrequencyKeys, &t, why))
        return false;
    t.inverting = invert.value_or(false);
    // SatNOGS DB derives alive from status ("active"); an older or a
    // trimmed copy may carry only one of them.
    t.alive = alive ? *alive : (status.isEmpty() || status == QLatin1String("active"));
    *out = t;
    return true;
}

// "entry 12 (ISS voice)": 1-based, as a person counts, with the
// description when there is one to read.
QString satnogsEntryName(qsizetype index, const QJsonValue &value)
{
    const QString description = value.toObject().value(QLatin1String("description")).toString();
    const QString number = QStringLiteral("entry %1").arg(index + 1);
    return description.isEmpty() ? number : QStringLiteral("%1 (%2)").arg(number, shown(description));
}

// ---- Gpredict .trsp ----------------------------------------------------

// The keys read (the key-file format's keys are case-sensitive, as
// Gpredict reads them); others (BAUD, a localised MODE[de]) are ignored.
const QStringList kTrspFrequencyKeys{QStringLiteral("UP_LOW"), QStringLiteral("UP_HIGH"), QStringLiteral("DOWN_LOW"),
                                     QStringLiteral("DOWN_HIGH")};

struct KeyValue {
    QString value;
    int line = 0;
};

struct TrspGroup {
    QString name;
    int line = 0;      // of its first header
    QString fault;     // a header that could not be read: the group is skipped
    QHash<QString, KeyValue> keys;
};

// The key-file format's escapes in a string value: \s \n \t \r \\. An
// unknown one is kept as written.
QString unescaped(const QString &value)
{
    QString out;
    out.reserve(value.size());
    for (qsizetype i = 0; i < value.size(); ++i) {
        const QChar c = value[i];
        if (c != u'\\' || i + 1 == value.size()) {
            out += c;
            continue;
        }
        const QChar next = value[++i];
        switch (next.unicode()) {
        case u's': out += u' '; break;
        case u'n': out += u'\n'; break;
        case u't': out += u'\t'; break;
        case u'r': out += u'\r'; break;
        case u'\\': out += u'\\'; break;
        default: out += c; out += next; break;
        }
    }
    return out;
}

// A group name as the key-file format allows it: not empty, no brackets,
// no control characters.
bool isGroupName(const QString &name)
{
    if (name.isEmpty())
        return false;
    for (const QChar c : name)
        if (c == u'[' || c == u']' || c.unicode() < 0x20 || c.unicode() == 0x7f)
            return false;
    return true;
}

// "line 7 [Mode V/U FM]": where a group's fault is.
QString trspWhere(int line, const QString &group)
{
    return QStringLiteral("line %1 [%2]").arg(line).arg(shown(group));
}

void readTrspGroup(const TrspGroup &group, int noradId, Collector *collector)
{
    if (!group.fault.isEmpty()) {
        collector->skip(QStringLiteral("line %1").arg(group.line), group.fault);
        return;
    }
    Transponder t;
    t.noradId = noradId;
    t.description = group.name;
    Frequencies f;
    std::optional<double> *edges[] = {&f.uplinkLow, &f.uplinkHigh, &f.downlinkLow, &f.downlinkHigh};
    QString why;
    for (int i = 0; i < 4; ++i) {
        const auto it = group.keys.constFind(kTrspFrequencyKeys[i]);
        if (it == group.keys.cend())
            continue;
        if (!frequencyFromText(it->value, edges[i], &why)) {
            collector->skip(trspWhere(it->line, group.name), kTrspFrequencyKeys[i] + QLatin1Char(' ') + why);
            return;
        }
    }
    if (!finishFrequencies(&f, kTrspFrequencyKeys, &t, &why)) {
        collector->skip(trspWhere(group.line, group.name), why);
        return;
    }
    const auto invert = group.keys.constFind(QStringLiteral("INVERT"));
    if (invert != group.keys.cend()) {
        // As GLib reads a boolean: true or 1, false or 0, nothing else. An
        // unreadable one is not taken as "not inverting": the wrong
        // sideband would steer the uplink the wrong way.
        const QString v = invert->value;
        if (v == QLatin1String("true") || v == QLatin1String("1")) {
            t.inverting = true;
        } else if (v != QLatin1String("false") && v != QLatin1String("0")) {
            collector->skip(trspWhere(invert->line, group.name),
                            QStringLiteral("INVERT %1 is not true or false").arg(quoted(v)));
            return;
        }
    }
    t.mode = unescaped(group.keys.value(QStringLiteral("MODE")).value);
    collector->result.transponders.append(t);
}

// The lines, into groups: a group named twice is one group, and a key
// given twice keeps its last value (as the key-file format has it).
QList<TrspGroup> trspGroups(const QString &text, Collector *collector)
{
    QList<TrspGroup> groups;
    QHash<QString, qsizetype> byName;
    qsizetype current = -1; // an index: appending may move the groups
    bool inBadGroup = false;
    const QList<QStringView> lines = QStringView(text).split(u'\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const int lineNumber = int(i + 1);
        const QStringView line = lines[i].trimmed();
        if (line.isEmpty() || line.startsWith(u'#'))
            continue;
        if (line.startsWith(u'[')) {
            const QString name = line.endsWith(u']') ? line.sliced(1, line.size() - 2).toString() : QString();
            inBadGroup = false;
            if (!line.endsWith(u']') || !isGroupName(name)) {
                TrspGroup bad;
                bad.line = lineNumber;
                bad.fault = QStringLiteral("%1 is not a [transponder name] header").arg(quoted(line.toString()));
                groups.append(bad);
                current = -1;
                inBadGroup = true;
                continue;
            }
            const auto it = byName.constFind(name);
            if (it != byName.cend()) {
                current = *it;
                continue;
            }
            current = groups.size();
            byName.insert(name, current);
            groups.append(TrspGroup{name, lineNumber, {}, {}});
            continue;
        }
        const qsizetype equals = line.indexOf(u'=');
        if (equals <= 0) {
            collector->skip(QStringLiteral("line %1").arg(lineNumber),
                            QStringLiteral("%1 is neither a [group], a KEY=value line nor a # comment")
                                .arg(quoted(line.toString())));
            continue;
        }
        if (inBadGroup)
            continue; // the header's message covers its lines
        if (current < 0) {
            collector->skip(QStringLiteral("line %1").arg(lineNumber),
                            QStringLiteral("%1 comes before any [transponder name] header").arg(quoted(line.toString())));
            continue;
        }
        const QString key = line.first(equals).trimmed().toString();
        groups[current].keys.insert(key, KeyValue{line.sliced(equals + 1).trimmed().toString(), lineNumber});
    }
    return groups;
}

QString sourceNameOf(const QString &name)
{
    return shown(name, 120);
}

} // namespace

QStringList TransponderImport::skipReport() const
{
    QStringList report = skipped;
    if (skippedCount > skipped.size())
        report.append(QStringLiteral("… and %1 more skipped").arg(skippedCount - skipped.size()));
    return report;
}

TransponderImport readSatnogsTransmitters(const QByteArray &json, const QString &sourceName)
{
    Collector collector{sourceNameOf(sourceName), {}};
    const QByteArray bytes = withoutByteOrderMark(json);
    if (!bytes.isValidUtf8())
        return collector.refuse(QStringLiteral("is not UTF-8 text, so not a SatNOGS DB transmitter list"));
    // Qt's parser refuses what is not JSON, and nesting past its limit, so
    // a deep file ends with an error rather than a deep recursion.
    QJsonParseError parseError{};
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &parseError);
    if (parseError.error != QJsonParseError::NoError)
        return collector.refuse(QStringLiteral("is not JSON: %1 at byte %2").arg(parseError.errorString()).arg(parseError.offset));
    if (!document.isArray())
        return collector.refuse(QStringLiteral("is a JSON %1, not the array of transmitters SatNOGS DB's "
                                               "/api/transmitters/ gives")
                                    .arg(document.isObject() ? QStringLiteral("object") : QStringLiteral("value")));
    const QJsonArray entries = document.array();
    for (qsizetype i = 0; i < entries.size(); ++i) {
        const QJsonValue value = entries.at(i);
        Transponder t;
        QString why;
        if (readSatnogsEntry(value, &t, &why))
            collector.result.transponders.append(t);
        else
            collector.skip(satnogsEntryName(i, value), why);
    }
    return collector.finish(int(entries.size()), "transmitters");
}

TransponderImport readSatnogsTransmittersFile(const QString &path)
{
    const input::BoundedRead read = input::readBoundedFile(path, kLargestTransmitterList);
    if (!read.ok()) {
        TransponderImport refused;
        refused.error = shown(read.error, 300);
        return refused;
    }
    return readSatnogsTransmitters(read.bytes, path);
}

TransponderImport readGpredictTrsp(const QByteArray &bytes, const QString &sourceName, int noradId)
{
    Collector collector{sourceNameOf(sourceName), {}};
    if (noradId < 1 || noradId > kLargestNoradId)
        return collector.refuse(QStringLiteral("%1 is not a catalogue number (1..%2)").arg(noradId).arg(kLargestNoradId));
    // The key-file format is UTF-8 throughout; GLib refuses other text too.
    const QByteArray text = withoutByteOrderMark(bytes);
    if (!text.isValidUtf8())
        return collector.refuse(QStringLiteral("is not UTF-8 text, so not a Gpredict .trsp file"));
    const QList<TrspGroup> groups = trspGroups(QString::fromUtf8(text), &collector);
    for (const TrspGroup &group : groups)
        readTrspGroup(group, noradId, &collector);
    return collector.finish(int(groups.size()), "transponder groups");
}

std::optional<int> noradIdFromTrspFileName(const QString &path)
{
    static const QRegularExpression name(QStringLiteral("^0*([1-9][0-9]{0,8})\\.trsp$"));
    const QRegularExpressionMatch match = name.match(QFileInfo(path).fileName());
    if (!match.hasMatch())
        return std::nullopt;
    return match.captured(1).toInt();
}

TransponderImport readGpredictTrspFile(const QString &path, std::optional<int> noradId)
{
    if (!noradId)
        noradId = noradIdFromTrspFileName(path);
    if (!noradId) {
        TransponderImport refused;
        refused.error = QStringLiteral("%1: cannot tell which satellite it is for: Gpredict names the file after the "
                                       "catalogue number (25544.trsp); rename it, or give the number")
                            .arg(sourceNameOf(path));
        return refused;
    }
    const input::BoundedRead read = input::readBoundedFile(path, kLargestTrspFile);
    if (!read.ok()) {
        TransponderImport refused;
        refused.error = shown(read.error, 300);
        return refused;
    }
    return readGpredictTrsp(read.bytes, path, *noradId);
}

} // namespace slew::radio
