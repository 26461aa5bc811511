r"""Eigenvalues and eigenvectors of a symmetric 3 x 3 matrix by Jacobi rotations, each zeroing the
largest off-diagonal element (the classical Jacobi method, Golub and Van Loan, Matrix
Computations, 8.5), in the arithmetic LAMMPS 22 Jul 2025's MathEigen::jacobi3 does it, so that a
molecule template's principal axes are LAMMPS's to the last bit: rotation angle from
:math:`\kappa = (M_{jj} - M_{ii}) / 2 M_{ij}`, :math:`t = \operatorname{sign}(\kappa) / (|\kappa| +
\sqrt{1 + \kappa^2})`, :math:`c = 1/\sqrt{1 + t^2}`, :math:`s = c t`; an element negligible beside
both its diagonal elements is set to 0; at most 50 sweeps; eigenvalues sorted decreasing.
"""

import math

MAX_SWEEPS = 50


def _largest_in_row(m, i):
    best = i + 1
    for j in range(i + 2, 3):
        if abs(m[i][j]) > abs(m[i][best]):
            best = j
    return best


def eigen3(matrix):
    """(eigenvalues (3,), eigenvectors as columns [[x0, x1, x2], ...]) of a symmetric 3 x 3 matrix
    (nested lists or an array), eigenvalues decreasing; None where the rotations do not converge."""
    n = 3
    m = [[float(matrix[i][j]) for j in range(n)] for i in range(n)]
    vectors = [[1.0 if i == j else 0.0 for j in range(n)] for i in range(n)]     # eigenvectors in rows
    row_max = [_largest_in_row(m, i) for i in range(n - 1)] + [0]
    converged = False
    for _ in range(MAX_SWEEPS * n * (n - 1) // 2):
        i, j = 0, row_max[0]
        largest = abs(m[i][j])
        for r in range(1, n - 1):
            if abs(m[r][row_max[r]]) > largest:
                largest, i, j = abs(m[r][row_max[r]]), r, row_max[r]
        if m[i][i] + m[i][j] == m[i][i] and m[j][j] + m[i][j] == m[j][j]:
            m[i][j] = 0.0
            row_max[i] = _largest_in_row(m, i)
        if m[i][j] == 0.0:
            converged = True
            break
        t = 1.0
        difference = m[j][j] - m[i][i]
        if difference != 0.0:
            kappa = difference
            t = 0.0
            if m[i][j] != 0.0:
                kappa /= 2.0 * m[i][j]
                t = 1.0 / (math.sqrt(1 + kappa * kappa) + abs(kappa))
                if kappa < 0.0:
                    t = -t
        c = 1.0 / math.sqrt(1 + t * t)
        s = c * t
        _rotate(m, row_max, i, j, c, s, t)
        for v in range(n):
            kept = vectors[i][v]
            vectors[i][v] = c * vectors[i][v] - s * vectors[j][v]
            vectors[j][v] = s * kept + c * vectors[j][v]
    if not converged:
        return None
    values = [m[k][k] for k in range(n)]
    for a in range(n - 1):
        top = a
        for b in range(a + 1, n):
            if values[b] > values[top]:
                top = b
        values[a], values[top] = values[top], values[a]
        vectors[a], vectors[top] = vectors[top], vectors[a]
    return values, [[vectors[k][d] for k in range(n)] for d in range(n)]


def _rotate(m, row_max, i, j, c, s, t):
    """m' = R^T m R in the (i, j) plane, the upper triangle kept (the lower holds the old values)."""
    n = 3
    m[i][i] -= t * m[i][j]
    m[j][j] += t * m[i][j]
    m[i][j] = 0.0
    for w in range(i):
        m[i][w] = m[w][i]
        m[w][i] = c * m[w][i] - s * m[w][j]
        _track(m, row_max, w, i)
    for w in range(i + 1, j):
        m[w][i] = m[i][w]
        m[i][w] = c * m[i][w] - s * m[w][j]
    for w in range(j + 1, n):
        m[w][i] = m[i][w]
        m[i][w] = c * m[i][w] - s * m[j][w]
    row_max[i] = _largest_in_row(m, i) if i < n - 1 else 0
    for w in range(i):
        m[w][j] = s * m[i][w] + c * m[w][j]
        _track(m, row_max, w, j)
    for w in range(i + 1, j):
        m[w][j] = s * m[w][i] + c * m[w][j]
        _track(m, row_max, w, j)
    for w in range(j + 1, n):
        m[j][w] = s * m[w][i] + c * m[j][w]
    row_max[j] = _largest_in_row(m, j) if j < n - 1 else 0


def _track(m, row_max, w, changed):
    if changed == row_max[w]:
        row_max[w] = _largest_in_row(m, w)
    elif abs(m[w][changed]) > abs(m[w][row_max[w]]):
        row_max[w] = changed
