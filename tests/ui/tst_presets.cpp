// Presets: named positions inside the limits, at most one per number key.

#include "model/presets.h"
#include "model/rotatorlimits.h"

#include <QJsonObject>
#include <QTest>

using slew::model::Preset;
using slew::model::PresetList;
using slew::model::RotatorLimits;

class TestPresets : public QObject {
    Q_OBJECT
private slots:
    void storeReplaceAndRemove()
    {
        PresetList list;
        const RotatorLimits limits;
        QCOMPARE(list.store({"  Moon  rise ", 95, 10}, limits), QString());
        QCOMPARE(list.at(0)->name, QStringLiteral("Moon rise"));
        QCOMPARE(list.store({"moon rise", 100, 12}, limits), QString()); // same name: replaced
        QCOMPARE(list.size(), 1);
        QCOMPARE(list.at(0)->azimuth, 100.0);
        QVERIFY(!list.store({"", 1, 1}, limits).isEmpty());
        QVERIFY(!list.store({"low", 10, -5}, limits).isEmpty());
        QVERIFY(!list.store({"far", 400, 5}, limits).isEmpty());
        QCOMPARE(list.size(), 1);
        QCOMPARE(list.remove(0), QString());
        QVERIFY(!list.remove(0).isEmpty());
    }

    void atMostOnePerNumberKey()
    {
        PresetList list;
        for (int i = 0; i < PresetList::kMaxPresets; ++i)
            QCOMPARE(list.store({QString::number(i), double(i), 0}, RotatorLimits{}), QString());
        QVERIFY(!list.store({"tenth", 1, 1}, RotatorLimits{}).isEmpty());
    }

    void jsonRoundTrip()
    {
        PresetList list;
        list.store({"a", 1.5, 2.5}, RotatorLimits{});
        list.store({"b", 300, 80}, RotatorLimits{});
        QString error;
        const auto back = PresetList::fromJson(list.toJson(), &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->presets(), list.presets());
        QJsonArray bad{QJsonObject{{"name", "x"}}};
        QVERIFY(!PresetList::fromJson(bad, &error));
        QVERIFY(!error.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestPresets)
#include "tst_presets.moc"
