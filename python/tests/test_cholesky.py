"""gab.Cholesky over libgab (run by ctest and .ci/run)."""

import unittest

import numpy as np

import gab


class CscLike:
    """What scipy.sparse's CSC matrices offer and gab reads."""

    format = "csc"

    def __init__(self, n, indptr, indices, data):
        self.shape = (n, n)
        self.indptr, self.indices, self.data = indptr, indices, data


def grid_laplacian(k, shift):
    """Lower triangle of the 5-point Laplacian of a k x k grid + shift I, and the dense matrix."""
    n = k * k
    dense = np.zeros((n, n))
    for y in range(k):
        for x in range(k):
            v = x + k * y
            dense[v, v] = 4 + shift
            for u in ([v + 1] if x + 1 < k else []) + ([v + k] if y + 1 < k else []):
                dense[u, v] = dense[v, u] = -1
    indptr, indices, data = [0], [], []
    for j in range(n):
        rows = np.nonzero(dense[j:, j])[0] + j
        indices += rows.tolist()
        data += dense[rows, j].tolist()
        indptr.append(len(indices))
    return CscLike(n, np.array(indptr), np.array(indices), np.array(data)), dense


class CholeskyTest(unittest.TestCase):
    def test_solve_one_and_several_right_hand_sides(self):
        A, dense = grid_laplacian(12, 0.1)
        chol = gab.Cholesky(A)
        b = np.sin(np.arange(A.shape[0]))
        x = chol.solve(b)
        self.assertEqual(x.shape, b.shape)
        self.assertLess(np.linalg.norm(dense @ x - b) / np.linalg.norm(b), 1e-12)
        B = np.stack([b, np.cos(np.arange(A.shape[0])), np.ones(A.shape[0])], 1)
        X = chol.solve(B)
        self.assertLess(np.linalg.norm(dense @ X - B) / np.linalg.norm(B), 1e-12)
        self.assertTrue(np.array_equal(X[:, 0], x))

    def test_add_anchor_equals_a_fresh_factorization(self):
        A, dense = grid_laplacian(10, 0.05)
        b = np.linspace(-1, 1, A.shape[0])
        chol = gab.Cholesky((A.indptr, A.indices, A.data))
        chol.add_anchor(37, 2.5)
        dense[37, 37] += 2.5 ** 2
        x = chol.solve(b)
        self.assertTrue(np.allclose(x, np.linalg.solve(dense, b), rtol=1e-11, atol=1e-12))
        # Refactoring with the original values discards the update.
        chol.factorize(A.data)
        dense[37, 37] -= 2.5 ** 2
        self.assertTrue(np.allclose(chol.solve(b), np.linalg.solve(dense, b), rtol=1e-11, atol=1e-12))

    def test_analyze_then_factorize(self):
        A, dense = grid_laplacian(6, 1.0)
        chol = gab.Cholesky().analyze((A.indptr, A.indices, None))
        with self.assertRaises(gab.GabError) as e:
            chol.solve(np.ones(A.shape[0]))
        self.assertEqual(e.exception.name, "GAB_E_STATE")
        chol.factorize(A)
        self.assertTrue(np.allclose(dense @ chol.solve(np.ones(36)), 1))

    def test_errors_raise_with_the_library_message(self):
        # Entries above the diagonal (the full matrix instead of its lower triangle).
        with self.assertRaises(gab.GabError) as e:
            gab.Cholesky((np.array([0, 2, 4]), np.array([0, 1, 0, 1]), np.array([2.0, -1, -1, 2])))
        self.assertEqual(str(e.exception),
                         "Cholesky.analyze: column 1: row 0 is above the diagonal (give the lower triangle)")
        with self.assertRaises(gab.GabError) as e:
            gab.Cholesky((np.array([0, 2, 3]), np.array([0, 1, 1]), np.array([1.0, 2, 1])))
        self.assertEqual(e.exception.name, "GAB_E_NOT_POSITIVE_DEFINITE")
        chol = gab.Cholesky((np.array([0, 2, 3]), np.array([0, 1, 1]), np.array([2.0, -1, 2])))
        with self.assertRaises(gab.GabError) as e:
            chol.add_anchor(2, 1.0)
        self.assertEqual(str(e.exception), "Cholesky.add_anchor: j = 2 is out of range [0, 2)")
        with self.assertRaises(ValueError):
            chol.solve(np.ones(3))
        with self.assertRaises(ValueError):
            chol.factorize((np.array([0, 1, 2]), np.array([0, 1]), np.array([1.0, 1.0])))

    def test_arguments_are_checked_not_coerced(self):
        chol = gab.Cholesky((np.array([0, 2, 3]), np.array([0, 1, 1]), np.array([2.0, -1, 2])))
        with self.assertRaisesRegex(ValueError, "j must be in"):
            chol.add_anchor(2**32 + 1, 1.0)  # not vertex 1
        with self.assertRaisesRegex(TypeError, "j must be an integer"):
            chol.add_anchor(1.7, 1.0)
        with self.assertRaisesRegex(TypeError, "w must be a number"):
            chol.add_anchor(1, "1.0")
        with self.assertRaisesRegex(TypeError, "indptr must hold integers"):
            gab.Cholesky((np.array([0.0, 2.0, 3.0]), np.array([0, 1, 1]), np.array([2.0, -1, 2])))
        with self.assertRaisesRegex(TypeError, "data must hold real numbers"):
            gab.Cholesky((np.array([0, 2, 3]), np.array([0, 1, 1]), np.array([2.0, -1, 2 + 1j])))
        with self.assertRaisesRegex(TypeError, "b must hold real numbers"):
            chol.solve(np.array([1.0, 1j]))


if __name__ == "__main__":
    unittest.main()
