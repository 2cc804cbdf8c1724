// SPDX-License-Identifier: GPL-3.0-or-later
// Favourite targets: marked and unmarked, kept in the settings and read back
// in order, a satellite kept by its number through a reload that lacks it
// (reported missing, by its last name) and renamed when a set names it anew.

#include "sky/favouritetargets.h"

#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

using namespace slew::sky;

namespace {

ElementSet satellite(int number, const QString &name)
{
    ElementSet t;
    t.catalogueNumber = number;
    t.name = name;
    return t;
}

} // namespace

class TestFavouriteTargets : public QObject {
    Q_OBJECT
private slots:
    void togglesAndPersists()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("favourites.ini"));
        FavouriteTargets favourites;
        QVERIFY(favourites.toggle(FavouriteTarget::satellite(satellite(25544, QStringLiteral("ISS (ZARYA)")))));
        QVERIFY(favourites.toggle(FavouriteTarget::moon()));
        QVERIFY(favourites.toggle(FavouriteTarget::satellite(satellite(33591, QStringLiteral("NOAA 19")))));
        // Nine digits, as the catalogue numbers objects since July 2026.
        QVERIFY(favourites.toggle(FavouriteTarget::satellite(satellite(270033591, QStringLiteral("NEW SAT")))));
        QVERIFY(!favourites.toggle(FavouriteTarget::moon())); // unmarked again
        QVERIFY(favourites.toggle(FavouriteTarget::sun()));
        {
            QSettings settings(file, QSettings::IniFormat);
            favourites.save(settings);
        }

        FavouriteTargets again;
        const QSettings settings(file, QSettings::IniFormat);
        again.load(settings);
        const QList<FavouriteTarget> list = again.list();
        QCOMPARE(list.size(), 4);
        QCOMPARE(list[0].catalogueNumber, 25544);
        QCOMPARE(list[0].name, QStringLiteral("ISS (ZARYA)"));
        QCOMPARE(list[1].name, QStringLiteral("NOAA 19"));
        QCOMPARE(list[2].catalogueNumber, 270033591);
        QCOMPARE(list[3].kind, FavouriteTarget::Kind::Sun);
        QVERIFY(!again.contains(FavouriteTarget::moon()));
        // The name is not part of who a satellite is.
        QVERIFY(again.contains(FavouriteTarget::satellite(satellite(25544, QStringLiteral("ISS")))));
    }

    void ignoresWhatItCannotRead()
    {
        QTemporaryDir dir;
        QSettings settings(dir.filePath(QStringLiteral("favourites.ini")), QSettings::IniFormat);
        settings.setValue(QLatin1String(FavouriteTargets::kSettingsKey),
                          QStringList{QStringLiteral("moon"), QStringLiteral("jupiter"), QStringLiteral("-3 X"),
                                      QStringLiteral("moon"), QStringLiteral("41617 FLOCK 2P-1")});
        FavouriteTargets favourites;
        favourites.load(settings);
        QCOMPARE(favourites.list().size(), 2);
        QCOMPARE(favourites.list()[1].name, QStringLiteral("FLOCK 2P-1"));
    }

    void aSatelliteMissingFromTheSetsIsKept()
    {
        FavouriteTargets favourites;
        favourites.toggle(FavouriteTarget::sun());
        favourites.toggle(FavouriteTarget::satellite(satellite(25544, QStringLiteral("ISS (ZARYA)"))));
        favourites.toggle(FavouriteTarget::satellite(satellite(99999, QStringLiteral("OBJECT A"))));

        const QList<ElementSet> without{satellite(99999, QStringLiteral("OBJECT A"))};
        const QList<FavouriteTarget> missing = favourites.missingFrom(without);
        QCOMPARE(missing.size(), 1);
        QCOMPARE(missing[0].name, QStringLiteral("ISS (ZARYA)"));
        QCOMPARE(favourites.list().size(), 3);

        const QList<ElementSet> reloaded{satellite(25544, QStringLiteral("ISS (ZARYA)")),
                                  satellite(99999, QStringLiteral("TINYSAT"))};
        QVERIFY(favourites.missingFrom(reloaded).isEmpty());
        QVERIFY(favourites.renameFrom(reloaded));
        QCOMPARE(favourites.list()[2].name, QStringLiteral("TINYSAT"));
        QVERIFY(!favourites.renameFrom(reloaded));
    }
};

QTEST_GUILESS_MAIN(TestFavouriteTargets)
#include "tst_favouritetargets.moc"
