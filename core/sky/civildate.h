// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Civil (proleptic Gregorian) dates and the Julian dates of their
// midnights, exactly, for any year an element set can carry: epochs come
// as a year and a day of the year (TLE) or as a calendar date (OMM), and
// SGP4 counts from the Julian date. Pure integer arithmetic, after the
// days-from-civil method (H. Hinnant, "chrono-Compatible Low-Level Date
// Algorithms"), so a date and its Julian day go both ways without rounding.

namespace slew::sky {

struct CivilDate {
    int year = 0;
    int month = 0;     // 1..12
    int day = 0;       // 1..31
    int dayOfYear = 0; // 1..366
};

bool isLeapYear(int year);
int daysInMonth(int year, int month);
// The Julian date of the date's midnight (always x.5). The date must be valid.
double julianDayOfDate(int year, int month, int day);
// The same for a day of the year, 1..366.
double julianDayOfYearDay(int year, int dayOfYear);
// The civil date of a Julian date's UTC day (a midnight x.5, or any time in it).
CivilDate civilDateOfJulian(double julian);

} // namespace slew::sky
