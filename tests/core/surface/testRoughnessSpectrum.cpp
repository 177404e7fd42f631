// SPDX-License-Identifier: GPL-3.0-or-later
// A surface from its roughness numbers (RoughnessSpectrum.hpp): the spectrum has the Rq and Rdq
// it was made from, on the band of the cut-offs; a power law of known Hurst exponent is found
// again from its own Rq and Rdq; Ra is Rq of Gaussian heights; a ratio no Hurst exponent in
// (0, 1] gives is refused with the range.
#include "ExpectParameterError.hpp"

#include "roughContact/Error.hpp"
#include "roughContact/surface/RoughnessSpectrum.hpp"
#include "roughContact/surface/SpectralMoments.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace roughContact;

TEST(RoughnessSpectrum, HasTheRqAndSlopeItWasMadeFromOnTheStandardsBand)
{
    const RoughnessSpectrum r = roughnessSpectrum(0.3e-6, 0.1);
    const Spectrum& s = r.spectrum;
    // The default band: lambda_c = 0.8 mm is L, levels i/L up to 1/lambda_s = 1/2.5 um: 320.
    EXPECT_DOUBLE_EQ(s.length(), 0.8e-3);
    ASSERT_EQ(s.size(), 320u);
    EXPECT_NEAR(s.frequencies().front(), 1250.0, 1e-9);
    EXPECT_NEAR(s.frequencies().back(), 4e5, 1e-6);
    const SpectralMoments m = spectralMoments(s);
    // Rq from b_m exactly (rounding only); Rdq to the bisection's tolerance on H (1e-14),
    // which moves the ratio by far less than 1e-9.
    EXPECT_NEAR(std::sqrt(m.m0) / 0.3e-6, 1.0, 1e-12);
    EXPECT_NEAR(std::sqrt(m.m2) / 0.1, 1.0, 1e-9);
    EXPECT_GT(r.hurst, 0.0);
    EXPECT_LE(r.hurst, 1.0);
}

TEST(RoughnessSpectrum, FindsTheHurstExponentOfAPowerLawAgain)
{
    // A power law of m = 1.3 (H = 0.8) on the band of cut-offs 2 mm and 10 um.
    const double L = 2e-3;
    const Spectrum law = Spectrum::powerLaw(1e-9, 1.3, 1.0 / L, 1.0 / 10e-6, L);
    const SpectralMoments m = spectralMoments(law);
    const RoughnessSpectrum r = roughnessSpectrum(std::sqrt(m.m0), std::sqrt(m.m2), L, 10e-6);
    EXPECT_NEAR(r.hurst, 0.8, 1e-9);
    EXPECT_NEAR(r.bm / 1e-9, 1.0, 1e-8);
    ASSERT_EQ(r.spectrum.size(), law.size());
    for (std::size_t i = 0; i < law.size(); ++i) {
        EXPECT_NEAR(r.spectrum.amplitudes()[i] / law.amplitudes()[i], 1.0, 1e-8) << i;
    }
}

TEST(RoughnessSpectrum, RaIsRqOfGaussianHeights)
{
    // <|z|> = sqrt(2/pi) sigma for a normal z.
    EXPECT_DOUBLE_EQ(rqFromRa(1e-6), std::sqrt(M_PI / 2.0) * 1e-6);
    expectParameterError([] { rqFromRa(-1e-6); }, "Ra");
}

TEST(RoughnessSpectrum, ARatioNoHurstExponentGivesIsRefusedWithTheRange)
{
    // Rdq/Rq = 1e3 1/m: below even H = 1 over 2.5 um .. 0.8 mm (a slope in percent, say).
    try {
        roughnessSpectrum(1e-6, 1e-3);
        ADD_FAILURE() << "accepted";
    } catch (const ParameterError& e) {
        EXPECT_EQ(e.parameter(), "slope");
        EXPECT_NE(std::string(e.what()).find("a Hurst exponent in (0, 1] gives"), std::string::npos) << e.what();
    }
    expectParameterError([] { roughnessSpectrum(1e-9, 10.0); }, "slope"); // far above H -> 0
    expectParameterError([] { roughnessSpectrum(-1e-6, 0.1); }, "Rq");
    // Out of range before any arithmetic: sqrt(pi/2) Ra and (Rdq/Rq)^2 would overflow.
    expectParameterError([] { rqFromRa(1.7e308); }, "Ra");
    expectParameterError([] { roughnessSpectrum(1e-15, 1e300); }, "slope");
    expectParameterError([] { roughnessSpectrum(1e-6, 0.1, 1e-6, 2e-6); }, "shortCutoff");
    expectParameterError([] { roughnessSpectrum(1e-6, 0.1, 1.0, 1e-7); }, "roughness surface"); // 1e7 levels
}
