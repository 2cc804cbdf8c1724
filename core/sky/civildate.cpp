// SPDX-License-Identifier: GPL-3.0-or-later
#include "civildate.h"

#include <cmath>

namespace slew::sky {
namespace {

// The Julian date of 1970-01-01 00:00 UTC: day 0 of the count below.
constexpr double kJulianOfUnixDay0 = 2440587.5;

// Days from 1970-01-01 to a civil date. The year is counted from March, so
// the leap day is the last of its year, and in eras of 400 years (146097
// days), so negative years need no special case.
long long daysFromCivil(long long year, int month, int day)
{
    year -= month <= 2 ? 1 : 0;
    const long long era = (year >= 0 ? year : year - 399) / 400;
    const long long yearOfEra = year - era * 400;
    const long long dayOfMarchYear = (153 * (month > 2 ? month - 3 : month + 9) + 2) / 5 + day - 1;
    const long long dayOfEra = yearOfEra * 365 + yearOfEra / 4 - yearOfEra / 100 + dayOfMarchYear;
    return era * 146097 + dayOfEra - 719468;
}

} // namespace

bool isLeapYear(int year)
{
    return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
}

int daysInMonth(int year, int month)
{
    static const int days[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (month < 1 || month > 12)
        return 0;
    return month == 2 && isLeapYear(year) ? 29 : days[month - 1];
}

double julianDayOfDate(int year, int month, int day)
{
    return kJulianOfUnixDay0 + double(daysFromCivil(year, month, day));
}

double julianDayOfYearDay(int year, int dayOfYear)
{
    return julianDayOfDate(year, 1, 1) + double(dayOfYear - 1);
}

CivilDate civilDateOfJulian(double julian)
{
    const long long days = (long long)std::floor(julian - kJulianOfUnixDay0);
    const long long shifted = days + 719468;
    const long long era = (shifted >= 0 ? shifted : shifted - 146096) / 146097;
    const long long dayOfEra = shifted - era * 146097;
    const long long yearOfEra = (dayOfEra - dayOfEra / 1460 + dayOfEra / 36524 - dayOfEra / 146096) / 365;
    const long long dayOfMarchYear = dayOfEra - (365 * yearOfEra + yearOfEra / 4 - yearOfEra / 100);
    const long long monthFromMarch = (5 * dayOfMarchYear + 2) / 153;
    CivilDate date;
    date.day = int(dayOfMarchYear - (153 * monthFromMarch + 2) / 5 + 1);
    date.month = int(monthFromMarch < 10 ? monthFromMarch + 3 : monthFromMarch - 9);
    date.year = int(yearOfEra + era * 400 + (date.month <= 2 ? 1 : 0));
    date.dayOfYear = int(days - daysFromCivil(date.year, 1, 1)) + 1;
    return date;
}

} // namespace slew::sky
