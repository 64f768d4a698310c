// SPDX-License-Identifier: MIT
#pragma once
/// \file
/// Gale's end coordinate xi and the catenary slope parameter sigma = V/H (Gale 1976; see
/// docs/explanation/physics.md, "Dimensionless groups", and docs/reference/references.md). Plain
/// functions of one number, used both to describe a solved catenary (dimensionless_groups) and to
/// build one from Gale's inputs (problem_builders).

namespace catena {

/// sigma(xi) = sign(xi) sqrt((1 + |xi|)^2 - 1), the inverse of xi = sign(sigma)(sqrt(1+sigma^2)-1).
double gale_sigma_from_xi(double xi);
/// xi(sigma) = sign(sigma)(sqrt(1 + sigma^2) - 1), computed without cancellation.
double gale_xi_from_sigma(double sigma);

}  // namespace catena
