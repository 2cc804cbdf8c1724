// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What became of an operator's intent, in one type for every face and
// every kind of station: done; refused, with the reason in the operator's
// words; or, for a station on a broker, sent and awaiting the station's
// answer, which comes later as StationFace::answered with the same id.
// A station in this process never awaits: its answer is at once.

#include <QMetaType>
#include <QString>

namespace slew::face {

class Outcome {
public:
    enum class Kind { Done, Refused, Awaiting };

    Outcome() = default; // done

    static Outcome done() { return Outcome(Kind::Done, {}); }
    // An empty reason is not a refusal: a refusal always says why.
    static Outcome refused(const QString &why);
    static Outcome awaiting(const QString &id) { return Outcome(Kind::Awaiting, id); }
    // Done when `why` is empty, else refused with it: the station's parts
    // answer a move with the reason it was refused, or nothing.
    static Outcome refusedIf(const QString &why) { return why.isEmpty() ? done() : refused(why); }

    Kind kind() const { return m_kind; }
    bool isDone() const { return m_kind == Kind::Done; }
    bool isRefused() const { return m_kind == Kind::Refused; }
    bool isAwaiting() const { return m_kind == Kind::Awaiting; }
    // Not refused: done, or on its way.
    bool isAccepted() const { return m_kind != Kind::Refused; }
    // Why it was refused; empty otherwise.
    QString reason() const { return m_kind == Kind::Refused ? m_text : QString(); }
    // The answer's id while it awaits; empty otherwise.
    QString id() const { return m_kind == Kind::Awaiting ? m_text : QString(); }

    friend bool operator==(const Outcome &, const Outcome &) = default;

private:
    Outcome(Kind kind, const QString &text) : m_kind(kind), m_text(text) {}
    Kind m_kind = Kind::Done;
    QString m_text;
};

inline Outcome Outcome::refused(const QString &why)
{
    return Outcome(Kind::Refused, why.isEmpty() ? QStringLiteral("refused, for no reason given") : why);
}

} // namespace slew::face

Q_DECLARE_METATYPE(slew::face::Outcome)
