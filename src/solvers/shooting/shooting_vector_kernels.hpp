// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Compiled kernels for the vector operations ARKODE's ERKStep performs on a shot's serial
/// N_Vectors ("Integrators" in docs/explanation/methods/shooting.md). Private to the shooting
/// solver.
///
/// Why. Debian's SUNDIALS 6.4.1 libraries (libsundials-dev) are built without optimisation: their
/// serial vector operations are loops that keep every index and pointer on the stack. A shot's
/// state is tiny (3 to 17 components), so those loops were most of an ERKStep step (measured: 9
/// linear combinations a step at ~1,400 instructions each, against ~150 for the whole right-hand
/// side of a 9-component test system). SUNDIALS lets an N_Vector carry its own operations (the
/// table `N_Vector::ops`, copied to every clone): the shot's vectors stay SUNDIALS serial vectors
/// (NV_DATA_S, NV_LENGTH_S) and only the element loops ERKStep, its error weights and its Hermite
/// interpolation call are replaced by the ones below, compiled with the project. Each computes
/// the same sums in the same order as SUNDIALS' serial version, one element at a time (so that an
/// output may alias any input).

#include <sundials/sundials_nvector.h>

namespace catena::internal {

/// Replaces the element loops of the serial N_Vector `vector` (N_VNew_Serial) by the project's
/// compiled ones: linear sum and combination, constant, scale, product, quotient, absolute value,
/// inverse, added constant, max norm, weighted RMS norm and minimum. Clones made afterwards
/// (ERKStep's stage vectors) inherit them.
void use_compiled_kernels(N_Vector vector);

}  // namespace catena::internal
