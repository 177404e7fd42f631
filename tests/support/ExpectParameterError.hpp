// SPDX-License-Identifier: GPL-3.0-or-later
// EXPECT_THROW of a roughContact::ParameterError whose parameter() names `entry`: a test that an
// error says which entry is wrong, not only that there is one.
#pragma once

#include "roughContact/Error.hpp"

#include <gtest/gtest.h>

#include <string>

template <class F>
void expectParameterError(F f, const std::string& entry)
{
    try {
        f();
        ADD_FAILURE() << "no ParameterError naming " << entry;
    } catch (const roughContact::ParameterError& e) {
        EXPECT_EQ(e.parameter(), entry) << e.what();
    }
}
