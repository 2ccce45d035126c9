"""gab.Cholesky over libgab (run by ctest and .ci/run)."""

import unittest

import numpy as np

import gab


class CscLike:
    """What scipy.sparse's CSC matrices offer and gab reads (scipy may be
    absent: gab reads them by duck typing, and so do these tests)."""

    format = "csc"

    def __init__(self, n, indptr, indices, data):
        self.shape = (n, n)
        self.indptr, self.indices, self.data = indptr, indices, data


class CooLike:
    """A scipy.sparse COO matrix's part gab uses: its format and tocsc()."""

    format = "coo"

    def __init__(self, dense):
        self.shape = dense.shape
        self.dense = dense
        self.converted = 0

    def tocsc(self):
        self.converted += 1
        return csc_of(self.dense)


class UnsortedCscLike(CscLike):
    """A CSC matrix whose rows are not sorted within a column and hold a
    duplicate (scipy allows both; has_canonical_format says so)."""

    has_canonical_format = False

    def copy(self):
        return UnsortedCscLike(self.shape[0], self.indptr.copy(), self.indices.copy(), self.data.copy())

    def sum_duplicates(self):
        """scipy's: rows sorted within each column, duplicates summed (on this copy)."""
        n = self.shape[0]
        columns = np.repeat(np.arange(n), np.diff(self.indptr))
        keys = columns * n + self.indices
        unique, which = np.unique(keys, return_inverse=True)
        self.data = np.bincount(which, weights=self.data)
        self.indices = unique % n
        self.indptr = np.concatenate([[0], np.cumsum(np.bincount(unique // n, minlength=n))])
        self.has_canonical_format = True


def csc_of(dense):
    """Every nonzero of a dense matrix, as a CscLike."""
    n = dense.shape[0]
    indptr, indices, data = [0], [], []
    for j in range(n):
        rows = np.nonzero(dense[:, j])[0]
        indices += rows.tolist()
        data += dense[rows, j].tolist()
        indptr.append(len(indices))
    return CscLike(n, np.array(indptr), np.array(indices), np.array(data))


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
        # Rows out of order within a column (the library reads the lower triangle as given).
        with self.assertRaises(gab.GabError) as e:
            gab.Cholesky((np.array([0, 2, 3]), np.array([1, 0, 1]), np.array([-1.0, 2, 2])))
        self.assertEqual(str(e.exception), "Cholesky.analyze: column 0 has an out-of-range or unsorted row index")
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


    def test_the_whole_symmetric_matrix_in_any_form(self):
        """As scikit-sparse's cholesky(A): the whole symmetric matrix, any
        sparse format, or a dense array; the lower triangle is what counts."""
        lower, dense = grid_laplacian(7, 0.2)
        b = np.cos(np.arange(dense.shape[0]))
        expected = gab.Cholesky(lower).solve(b)
        whole = csc_of(dense)
        self.assertGreater(len(whole.data), len(lower.data))
        for name, A in [("csc", whole), ("tuple", (whole.indptr, whole.indices, whole.data)), ("dense", dense),
                        ("coo", CooLike(dense))]:
            with self.subTest(form=name):
                chol = gab.Cholesky(A)
                self.assertTrue(np.array_equal(chol.solve(b), expected))
                self.assertTrue(np.array_equal(chol(b), expected))  # a factor is called as scikit-sparse's
                chol.add_anchor(5, 2.0).factorize(A)  # refactored from the same form
                self.assertTrue(np.array_equal(chol.solve(b), expected))
        coo = CooLike(dense)
        gab.Cholesky(coo)
        self.assertEqual(coo.converted, 1)  # converted once, analyzed and factorized from it
        # Unsorted rows and a duplicate entry (allowed by scipy): summed on a copy, the caller's left alone.
        unsorted = UnsortedCscLike(2, np.array([0, 3, 5]), np.array([1, 0, 0, 1, 0]), np.array([-1, 1.5, 0.5, 2, -1]))
        self.assertTrue(np.allclose(gab.Cholesky(unsorted).solve(np.array([1.0, 1.0])), [1, 1]))
        self.assertFalse(unsorted.has_canonical_format)
        # A pattern alone, then the values.
        chol = gab.Cholesky().analyze((whole.indptr, whole.indices, None)).factorize(dense)
        self.assertTrue(np.array_equal(chol.solve(b), expected))
        chol.factorize(lower.data)  # the lower triangle's values, in its CSC order
        with self.assertRaisesRegex(ValueError, r"^Cholesky.factorize: values has \d+ entries, the analyzed lower "
                                                r"triangle \d+ \(give the matrix itself"):
            chol.factorize(whole.data)

    def test_a_matrix_that_is_not_symmetric_is_refused_clearly(self):
        hint = r" \(give the whole symmetric matrix or its lower triangle\)$"
        with self.assertRaisesRegex(ValueError, r"^Cholesky.analyze: A is not symmetric: A\[1, 0\] = -1.0 but "
                                                r"A\[0, 1\] = -0.5" + hint):
            gab.Cholesky(np.array([[2.0, -0.5], [-1, 2]]))
        with self.assertRaisesRegex(ValueError, r"^Cholesky.analyze: A is not symmetric: A\[1, 0\] = 0.0 but "
                                                r"A\[0, 1\] = 1.0" + hint):
            gab.Cholesky((np.array([0, 1, 3]), np.array([0, 0, 1]), np.array([2.0, 1, 2])))  # an upper triangle
        with self.assertRaisesRegex(ValueError, r"^Cholesky.analyze: A is not symmetric: it has entry \(0, 1\) "
                                                r"and not \(1, 0\)" + hint):
            gab.Cholesky().analyze((np.array([0, 1, 3]), np.array([0, 0, 1]), None))
        # An explicit zero without its mirror is no asymmetry.
        zero = (np.array([0, 2, 4, 6]), np.array([0, 1, 0, 1, 0, 2]), np.array([2.0, -1, -1, 2, 0, 2]))
        self.assertTrue(np.allclose(gab.Cholesky(zero).solve(np.array([1.0, 1, 2])), [1, 1, 1]))
        # Rounding is not asymmetry: 1e-10 of the largest entry is allowed.
        near = np.array([[4.0, 1.0], [1.0 + 1e-15, 3.0]])
        self.assertTrue(np.allclose(gab.Cholesky(near).solve(near @ np.ones(2)), 1))
        with self.assertRaisesRegex(ValueError, r"^Cholesky.analyze: a dense matrix must be square and 2-D, got "
                                                r"shape \(2, 3\)$"):
            gab.Cholesky(np.ones((2, 3)))
        with self.assertRaisesRegex(TypeError, r"^Cholesky.analyze: A must be a scipy.sparse matrix, a dense 2-D "
                                               r"numpy array or a tuple \(indptr, indices, data\), got list$"):
            gab.Cholesky([[2.0, 1.0], [1.0, 2.0]])
        with self.assertRaisesRegex(ValueError, r"^Cholesky.analyze: indices must be in 0..1, got 2$"):
            gab.Cholesky((np.array([0, 2, 3]), np.array([0, 2, 1]), np.array([2.0, -1, 2])))

    def test_every_ordering_and_thread_count_solves(self):
        """ordering= and threads= are `gab factor`'s: every ordering solves;
        they differ in the factor (natural order fills a grid's band, AMD and
        nested dissection far less); 'auto' is AMD below 100,000 columns; the
        thread count changes nothing of the result."""
        A, dense = grid_laplacian(30, 0.05)
        b = np.stack([np.sin(np.arange(A.shape[0])), np.ones(A.shape[0])], 1)
        entries = {}
        for ordering in ("amd", "nd", "natural", "auto"):
            one_thread = None
            for threads in (1, 2, 0):
                with self.subTest(ordering=ordering, threads=threads):
                    chol = gab.Cholesky(A, ordering=ordering, threads=threads)
                    x = chol.solve(b)
                    self.assertLess(np.linalg.norm(dense @ x - b) / np.linalg.norm(b), 1e-12)
                    if one_thread is None:
                        one_thread = x
                        entries[ordering] = chol.factor_entries
                    else:
                        self.assertTrue(np.array_equal(x, one_thread))
                        self.assertEqual(chol.factor_entries, entries[ordering])
        self.assertGreater(entries["natural"], 1.5 * entries["amd"])
        self.assertGreater(entries["natural"], 1.5 * entries["nd"])
        self.assertEqual(entries["auto"], entries["amd"])
        self.assertEqual(gab.Cholesky(A).factor_entries, entries["amd"])  # the default
        # analyze keeps the constructor's ordering.
        chol = gab.Cholesky(ordering="natural").analyze(A)
        self.assertEqual(chol.factor_entries, entries["natural"])
        self.assertTrue(np.allclose(dense @ chol.factorize(A).solve(b), b, rtol=0, atol=1e-12))

    def test_ordering_and_threads_are_checked(self):
        A, _ = grid_laplacian(4, 0.5)
        orderings = "'amd', 'nd', 'natural' or 'auto'"
        for error, pattern, call in [
            (ValueError, rf"^gab\.Cholesky: ordering must be {orderings}, got 'AMD'$",
             lambda: gab.Cholesky(A, ordering="AMD")),
            (ValueError, rf"^gab\.Cholesky: ordering must be {orderings}, got 'given'$",
             lambda: gab.Cholesky(ordering="given")),
            (TypeError, rf"^gab\.Cholesky: ordering must be {orderings}, got NoneType$",
             lambda: gab.Cholesky(A, ordering=None)),
            (ValueError, r"^gab\.Cholesky: threads must be in 0\.\.64, got 65$",
             lambda: gab.Cholesky(A, threads=65)),
            (ValueError, r"^gab\.Cholesky: threads must be in 0\.\.64, got -1$",
             lambda: gab.Cholesky(threads=-1)),
            (TypeError, r"^gab\.Cholesky: threads must be an integer, got float$",
             lambda: gab.Cholesky(A, threads=2.0)),
        ]:
            with self.subTest(pattern=pattern):
                with self.assertRaisesRegex(error, pattern):
                    call()
        with self.assertRaisesRegex(gab.GabError, r"^Cholesky.factor_entries: no analyzed matrix"):
            gab.Cholesky().factor_entries

    def test_a_closed_factor_says_it_is_closed(self):
        A, dense = grid_laplacian(4, 0.5)
        chol = gab.Cholesky(A)
        chol.close()
        for name, call in [("solve", lambda: chol.solve(np.ones(16))), ("add_anchor", lambda: chol.add_anchor(1, 1.0)),
                           ("factorize", lambda: chol.factorize(A))]:
            with self.subTest(call=name):
                with self.assertRaises(gab.GabError) as e:
                    call()
                self.assertEqual(e.exception.name, "GAB_E_STATE")
                self.assertRegex(str(e.exception), rf"^Cholesky.{name}: this Cholesky is closed \(close\(\) or the "
                                                   r"end of its with block released it\)")
        with gab.Cholesky(A) as scoped:
            pass
        with self.assertRaisesRegex(gab.GabError, "is closed"):
            scoped.solve(np.ones(16))
        chol.analyze(A).factorize(A)  # analyzing again reopens it
        self.assertTrue(np.allclose(dense @ chol.solve(np.ones(16)), 1))
        with self.assertRaisesRegex(gab.GabError, r"^Cholesky.solve: no analyzed matrix: call analyze first$"):
            gab.Cholesky().solve(np.ones(2))


if __name__ == "__main__":
    unittest.main()
