"""One Kalman update of a 2-state filter with H = I, by hand (nested lists, no numpy): the
reference the rostests of covariance blocks compare a node's ~state with
(test/covariance_block_test.py, test/gps_covariance_test.py)."""


def inverse(m):
    (a, b), (c, d) = m
    det = a * d - b * c
    return [[d / det, -b / det], [-c / det, a / det]]


def product(m, n):
    return [[sum(m[i][k] * n[k][j] for k in range(2)) for j in range(2)] for i in range(2)]


def update(x, P, z, R):
    """One Kalman update with H = I: K = P (P + R)^-1, x + K (z - x), (I - K) P."""
    K = product(P, inverse([[P[i][j] + R[i][j] for j in range(2)] for i in range(2)]))
    y = [z[0] - x[0], z[1] - x[1]]
    x = [x[i] + K[i][0] * y[0] + K[i][1] * y[1] for i in range(2)]
    IK = [[(1.0 if i == j else 0.0) - K[i][j] for j in range(2)] for i in range(2)]
    return x, product(IK, P)
