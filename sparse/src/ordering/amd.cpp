// Approximate minimum degree ordering, written (clean-room) from the published
// descriptions:
//
//   [ADD96] P. R. Amestoy, T. A. Davis, I. S. Duff, "An approximate minimum degree
//           ordering algorithm", SIAM J. Matrix Anal. Appl. 17(4):886-905, 1996.
//   [Dav06] T. A. Davis, "Direct Methods for Sparse Linear Systems", SIAM 2006, sec. 7.1.
//
// The quotient graph ([ADD96] sec. 2). After some pivots have been eliminated the graph
// holds *variables* (uneliminated; each is a supervariable standing for |i| = nv(i)
// indistinguishable rows) and *elements* (eliminated pivots; element e stands for the
// clique on its variable list L_e). Variable i keeps two lists,
//
//     E_i  the elements adjacent to i,      A_i  the variables adjacent to i,
//
// and its row in the partially factored matrix has the pattern A_i ∪ (∪_{e∈E_i} L_e) \ {i}.
// Eliminating the pivot p forms the new element
//
//     L_p = (A_p ∪ ∪_{e∈E_p} L_e) \ {p},                                          (1)
//
// and every e ∈ E_p is absorbed into p (its clique is contained in L_p's). |L_p| is the
// exact column count of p in the factor.
//
// Approximate external degree ([ADD96] sec. 3). For i ∈ L_p, with k variables eliminated,
//
//     d_i ≈ min( n - k - |i|,
//                d_i^old + |L_p \ i|,
//                |A_i \ i| + |L_p \ i| + Σ_{e ∈ E_i \ {p}} |L_e \ L_p| ),            (2)
//
// an upper bound on the true external degree. The set differences |L_e \ L_p| for every
// element touching L_p cost one pass over the E_i of i ∈ L_p: starting from w(e) = |L_e|,
// subtract |i| for each i ∈ L_p ∩ L_e. An element with |L_e \ L_p| = 0 is a subset of
// L_p and is absorbed too ("aggressive absorption"). A variable whose only neighbour left
// is p is eliminated with it ("mass elimination"); variables with identical lists (found
// by a hash of the lists, then compared) are merged into one supervariable. The bound (2)
// uses only weighted sizes, so each i ∈ L_p costs time proportional to its own lists.
//
// Rows with more than max(16, dense·sqrt(n)) entries are removed first and ordered last
// (they would make every degree update expensive and are filled in anyway). Variables are
// finally renumbered by a postorder of the assembly tree (element e's parent is the element
// that absorbed it), each element's block of variables kept contiguous: an equivalent
// ordering (same factor pattern), whose supernodes are runs of consecutive columns.
//
// Storage. All lists live in one int32 array `iw` with elbow room: variable i's list is
// iw[pe(i) .. pe(i) + len(i)), its first elen(i) entries are E_i, the rest A_i; element
// e's list is L_e. New elements are appended at `pfree`; when the array is full, the live
// lists are slid to the front (garbage collection). All workspace is allocated once,
// before the elimination starts; the elimination itself allocates nothing.

#include "gab/sparse/amd.h"
#include "gab/sparse/amd_graph.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

namespace gab {
namespace {

constexpr int32_t kNone = -1;

// Node::elen of a node that is no longer a variable.
constexpr int32_t kElement = -1;  // a pivot: eliminated, stands for an element
constexpr int32_t kMerged = -2;   // merged into another supervariable (link: its principal)
constexpr int32_t kMassElim = -3; // eliminated with the pivot link[i] (mass elimination)
constexpr int32_t kDense = -4;    // dense row, postponed to the end

class AmdOrdering {
 public:
  // Everything the elimination keeps per node, 32 bytes: a visit to a node touches most
  // of these fields together, so one cache miss brings them all (rather than one miss
  // per array with a structure-of-arrays layout).
  struct Node {
    int32_t pe;      // start of the node's list in iw_, kNone when it has none
    int32_t len;     // length of the list
    int32_t elen;    // variable: |E_i|; otherwise kElement / kMerged / kMassElim / kDense
    int32_t nv;      // variable: supervariable weight |i|, negated while i ∈ L_p;
                     // element: variables its pivot eliminated; 0 for merged / mass-eliminated
    int32_t degree;  // variable: approximate external degree; element: weighted |L_e|
    int32_t w;       // element: tag + |L_e \ L_p| during a pivot, 0 once absorbed;
                     // variables: marks for the supervariable comparison
    int32_t next;    // degree list (doubly linked); hash bucket while in L_p
    int32_t prev;    // degree list; the hash while in L_p
  };

  // `nodes` has n entries, `heads` 3 n words.
  // Vertices from `inner` on (inner <= n) are a halo: in the graph, never pivots.
  AmdOrdering(int32_t n, Node* nodes, int32_t* heads, const AmdOptions& options, int32_t inner = -1)
      : n_(n), inner_(inner < 0 ? n : inner), aggressive_(options.aggressive), nd_(nodes) {
    head_ = heads;
    hhead_ = heads + n;
    link_ = heads + 2 * static_cast<size_t>(n);
  }

  // Validates the lower triangle and counts each node's off-diagonal entries in len;
  // returns their total over both triangles in *nzfull.
  Status count_entries(const CscMatrix& lower, int64_t* nzfull);
  // Fills iw (iwlen >= *nzfull words) with the adjacency lists, removes dense rows and
  // sets up the degree lists.
  void build_graph(const CscMatrix& lower, int32_t* iw, int32_t iwlen, const AmdOptions& options);
  // The same from full adjacency lists (amd_graph.h): no validation, no transpose.
  void build_graph(int32_t nz, const int32_t* xadj, const int32_t* adj, int32_t* iw, int32_t iwlen,
                   const AmdOptions& options);
  void eliminate();
  void order(int32_t* perm);
  void fill_info(AmdInfo* info) const;

 private:
  void remove_from_degree_list(int32_t i);
  void insert_in_degree_list(int32_t i, int32_t deg);
  int32_t select_pivot();
  void build_element(int32_t me);
  void set_differences();
  void update_degrees(int32_t me);
  void merge_supervariables();
  void finalize_degrees(int32_t me);
  int32_t collect_garbage(int32_t scan_end);
  void reset_tags();
  void count_block(int64_t f, int64_t r);
  void init_lists(const AmdOptions& options);

  const int32_t n_;
  const int32_t inner_;  // vertices [inner_, n_) are the halo
  const bool aggressive_;
  int32_t iwlen_ = 0;

  Node* const nd_;         // n nodes
  int32_t* head_;          // head_[d]: first variable of approximate degree d
  int32_t* hhead_;         // hash bucket heads (all empty between pivots)
  int32_t* link_;          // element: the element that absorbed it (kNone: a root);
                           // merged: its principal; mass-eliminated: its pivot
  int32_t* iw_ = nullptr;  // the lists, iwlen_ words

  int32_t pfree_ = 0;     // first free word at the end of iw_
  int32_t tag_ = 2;       // w values >= tag_ were set during the current pivot
  int32_t tag_limit_ = 0; // reset the tags before tag_ passes this
  int32_t lemax_ = 0;     // largest weighted element size so far
  int32_t mindeg_ = 0;
  int32_t nel_ = 0;       // variables eliminated (dense rows count as eliminated)
  int32_t ndense_ = 0;
  int32_t compressions_ = 0;

  // Current pivot.
  int32_t pme1_ = 0, pme2_ = 0;  // L_p is iw_[pme1_ .. pme2_)
  int32_t degme_ = 0;            // weighted |L_p|
  int32_t nvpiv_ = 0;            // variables eliminated by this pivot

  int64_t lnz_ = 0;     // off-diagonal nonzeros of L
  double flops_ = 0.0;  // sum over columns of |L(:,j)|^2
};

void AmdOrdering::remove_from_degree_list(int32_t i) {
  const int32_t nx = nd_[i].next, pv = nd_[i].prev;
  if (nx != kNone) nd_[nx].prev = pv;
  if (pv != kNone) {
    nd_[pv].next = nx;
  } else {
    head_[nd_[i].degree] = nx;
  }
}

void AmdOrdering::insert_in_degree_list(int32_t i, int32_t deg) {
  // Head insertion: among equal degrees the most recently updated variable is taken
  // first, as in [ADD96] (it tends to continue the current front).
  const int32_t h = head_[deg];
  nd_[i].next = h;
  nd_[i].prev = kNone;
  if (h != kNone) nd_[h].prev = i;
  head_[deg] = i;
}

Status AmdOrdering::count_entries(const CscMatrix& lower, int64_t* nzfull) {
  const int32_t n = n_;
  const int32_t* colptr = lower.colptr.data();
  const int32_t* rowind = lower.rowind.data();
  for (int32_t i = 0; i < n; ++i) nd_[i].len = 0;
  int64_t total = 0;
  for (int32_t j = 0; j < n; ++j) {
    const int32_t begin = colptr[j], end = colptr[j + 1];
    if (end < begin || static_cast<size_t>(end) > lower.rowind.size()) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "amd_order: colptr is not monotone or exceeds rowind at column " +
                               std::to_string(j));
    }
    // Rows strictly increasing within [j, n): a well-formed lower triangle.
    int32_t last = j - 1;
    for (int32_t p = begin; p < end; ++p) {
      const int32_t i = rowind[p];
      if (i <= last || i >= n) {
        return Status::Error(StatusCode::kInvalidArgument,
                             "amd_order: column " + std::to_string(j) + " has row " +
                                 std::to_string(i) +
                                 " (rows must be strictly increasing, in the lower triangle "
                                 "and below n)");
      }
      last = i;
      ++nd_[i].len;
    }
    // The loop above counted the diagonal entry (first in the column, if present) in
    // nd_[j].len; take it back while adding the entries below it.
    const int32_t diagonal = begin < end && rowind[begin] == j ? 1 : 0;
    const int32_t below = end - begin - diagonal;
    nd_[j].len += below - diagonal;
    total += 2 * int64_t{below};
  }
  *nzfull = total;
  return Status::Ok();
}

// Builds the full adjacency (both triangles, no diagonal) in iw, sorted within each list,
// removes dense rows and fills the degree lists.
void AmdOrdering::build_graph(const CscMatrix& lower, int32_t* iw, int32_t iwlen,
                              const AmdOptions& options) {
  const int32_t n = n_;
  const int32_t* colptr = lower.colptr.data();
  const int32_t* rowind = lower.rowind.data();
  iw_ = iw;
  iwlen_ = iwlen;
  int32_t pos = 0;
  for (int32_t i = 0; i < n; ++i) {
    nd_[i].pe = pos;
    head_[i] = pos;  // insertion cursor
    pos += nd_[i].len;
  }
  pfree_ = pos;
  // Column j appends its larger neighbours to its own list after the smaller ones,
  // which earlier columns appended: every list comes out sorted.
  int32_t* const cursor = head_;
  for (int32_t j = 0; j < n; ++j) {
    int32_t begin = colptr[j];
    const int32_t end = colptr[j + 1];
    if (begin < end && rowind[begin] == j) ++begin;  // the diagonal comes first
    int32_t cj = cursor[j];
    for (int32_t p = begin; p < end; ++p) {
      const int32_t i = rowind[p];
      iw[cj++] = i;
      iw[cursor[i]++] = j;
    }
    cursor[j] = cj;
  }
  init_lists(options);
}

void AmdOrdering::build_graph(int32_t nz, const int32_t* xadj, const int32_t* adj, int32_t* iw, int32_t iwlen,
                              const AmdOptions& options) {
  iw_ = iw;
  iwlen_ = iwlen;
  for (int32_t i = 0; i < n_; ++i) {
    nd_[i].pe = xadj[i];
    nd_[i].len = xadj[i + 1] - xadj[i];
  }
  std::copy(adj, adj + nz, iw);
  pfree_ = nz;
  init_lists(options);
}

// Removes dense rows and fills the degree lists once iw holds the graph.
void AmdOrdering::init_lists(const AmdOptions& options) {
  const int32_t n = n_;
  for (int32_t i = 0; i < n; ++i) {
    nd_[i].nv = 1;
    nd_[i].elen = 0;
    nd_[i].w = 1;
    link_[i] = kNone;
    head_[i] = kNone;
    hhead_[i] = kNone;
    nd_[i].degree = nd_[i].len;
  }
  tag_ = 2;
  // Step 5 of a pivot uses tags up to tag_ + lemax + 1 + |L_p| <= tag_ + 2n + 1.
  tag_limit_ = static_cast<int32_t>(std::numeric_limits<int32_t>::max() - 2 * int64_t{n} - 2);

  if (options.dense >= 0.0 && inner_ == n_) {
    const double threshold = std::max(16.0, options.dense * std::sqrt(static_cast<double>(n)));
    for (int32_t i = 0; i < n; ++i) {
      if (static_cast<double>(nd_[i].len) > threshold) {
        nd_[i].elen = kDense;
        nd_[i].nv = 0;  // skipped wherever it still appears in a list
        nd_[i].pe = kNone;
        nd_[i].len = 0;
        ++ndense_;
      }
    }
    if (ndense_ > 0) {
      // Degrees count the graph without the dense rows.
      for (int32_t i = 0; i < n; ++i) {
        if (nd_[i].elen == kDense) continue;
        int32_t d = 0;
        for (int32_t p = nd_[i].pe; p < nd_[i].pe + nd_[i].len; ++p) d += nd_[iw_[p]].nv;
        nd_[i].degree = d;
      }
    }
  }
  nel_ = ndense_;
  for (int32_t i = 0; i < inner_; ++i) {
    if (nd_[i].elen != kDense) insert_in_degree_list(i, nd_[i].degree);
  }
  mindeg_ = 0;
}

int32_t AmdOrdering::select_pivot() {
  while (head_[mindeg_] == kNone) ++mindeg_;
  const int32_t me = head_[mindeg_];
  remove_from_degree_list(me);
  return me;
}

void AmdOrdering::reset_tags() {
  // Live elements and variables get 1 (< any tag); absorbed elements keep 0.
  for (int32_t i = 0; i < n_; ++i) {
    if (nd_[i].w != 0) nd_[i].w = 1;
  }
  tag_ = 2;
}

// Slides every live list to the front of iw_ (lists start below scan_end) and returns the
// first free word. The first word of each list is replaced by -(node+1) so that a
// left-to-right sweep can tell where lists start; the displaced word waits in pe.
int32_t AmdOrdering::collect_garbage(int32_t scan_end) {
  ++compressions_;
  for (int32_t j = 0; j < n_; ++j) {
    if (nd_[j].pe != kNone && nd_[j].len > 0) {
      const int32_t p = nd_[j].pe;
      nd_[j].pe = iw_[p];
      iw_[p] = -(j + 1);
    }
  }
  int32_t dst = 0;
  int32_t q = 0;
  while (q < scan_end) {
    const int32_t v = iw_[q++];
    if (v >= 0) continue;  // a dead word
    const int32_t j = -(v + 1);
    const int32_t first = nd_[j].pe;
    nd_[j].pe = dst;
    iw_[dst++] = first;
    const int32_t rest = nd_[j].len - 1;
    std::memmove(iw_ + dst, iw_ + q, sizeof(int32_t) * static_cast<size_t>(rest));
    dst += rest;
    q += rest;
  }
  return dst;
}

// Forms L_p by (1), removes its variables from the degree lists and flags them by
// negating nv; absorbs the elements of E_p.
void AmdOrdering::build_element(int32_t me) {
  int32_t* const iw = iw_;
  int32_t degme = 0;
  if (nd_[me].elen == 0) {
    // No adjacent elements: L_p ⊆ A_p, built in place over p's own list.
    int32_t dst = nd_[me].pe;
    pme1_ = dst;
    const int32_t end = nd_[me].pe + nd_[me].len;
    for (int32_t q = nd_[me].pe; q < end; ++q) {
      const int32_t j = iw[q];
      const int32_t nvj = nd_[j].nv;
      if (nvj <= 0) continue;
      degme += nvj;
      nd_[j].nv = -nvj;
      iw[dst++] = j;
      if (j < inner_) remove_from_degree_list(j);
    }
    pme2_ = dst;
  } else {
    // Append L_p at the end of iw_: scan L_e for e ∈ E_p, then A_p.
    int32_t dst = pfree_;
    pme1_ = dst;
    int32_t q = nd_[me].pe;  // next unread word of p's list
    int32_t qend = q + nd_[me].len;
    const int32_t ne = nd_[me].elen;
    for (int32_t k = 0; k <= ne; ++k) {
      int32_t e, src, cnt;
      if (k < ne) {
        e = iw[q++];
        if (nd_[e].pe == kNone) continue;  // defensive: already absorbed
        src = nd_[e].pe;
        cnt = nd_[e].len;
      } else {
        e = me;
        src = q;
        cnt = qend - q;
      }
      for (; cnt > 0; --cnt) {
        const int32_t j = iw[src++];
        const int32_t nvj = nd_[j].nv;
        if (nvj <= 0) continue;
        if (dst >= iwlen_) {
          // Out of room. Record what is still unread, compact, and move the part of
          // L_p built so far behind the compacted lists. Live data never grows (L_p
          // is no longer than what was read for it), so this always frees room.
          if (e == me) {
            nd_[me].pe = src;
            nd_[me].len = cnt - 1;
            nd_[me].elen = 0;
          } else {
            nd_[me].pe = q;
            nd_[me].len = qend - q;
            nd_[me].elen = ne - k - 1;
            nd_[e].pe = src;
            nd_[e].len = cnt - 1;
          }
          const int32_t built = dst - pme1_;
          const int32_t free_start = collect_garbage(pme1_);
          std::memmove(iw + free_start, iw + pme1_, sizeof(int32_t) * static_cast<size_t>(built));
          pme1_ = free_start;
          dst = free_start + built;
          if (e == me) {
            src = nd_[me].pe;
          } else {
            q = nd_[me].pe;
            qend = q + nd_[me].len;
            src = nd_[e].pe;
          }
        }
        degme += nvj;
        nd_[j].nv = -nvj;
        iw[dst++] = j;
        if (j < inner_) remove_from_degree_list(j);
      }
      if (e != me) {
        // e ⊆ L_p: absorbed.
        link_[e] = me;
        nd_[e].w = 0;
        nd_[e].pe = kNone;
        nd_[e].len = 0;
      }
    }
    pme2_ = dst;
    pfree_ = dst;
  }
  degme_ = degme;
  nd_[me].pe = pme1_;
  nd_[me].len = pme2_ - pme1_;
  nd_[me].elen = kElement;
}

// For every element e adjacent to some i ∈ L_p, leaves w(e) = tag + |L_e \ L_p|.
void AmdOrdering::set_differences() {
  const int32_t* const iw = iw_;
  const int32_t tag = tag_;
  for (int32_t p = pme1_; p < pme2_; ++p) {
    const int32_t i = iw[p];
    const int32_t eln = nd_[i].elen;
    if (eln <= 0) continue;
    const int32_t nvi = -nd_[i].nv;
    const int32_t first_visit = tag - nvi;
    for (int32_t q = nd_[i].pe, end = nd_[i].pe + eln; q < end; ++q) {
      const int32_t e = iw[q];
      const int32_t we = nd_[e].w;
      if (we >= tag) {
        nd_[e].w = we - nvi;
      } else if (we != 0) {
        nd_[e].w = nd_[e].degree + first_visit;
      }
    }
  }
}

// Prunes E_i and A_i of every i ∈ L_p, computes the third term of (2) without |L_p \ i|,
// absorbs elements inside L_p, mass-eliminates variables left adjacent to p alone, puts p
// at the front of E_i and files i under the hash of its lists.
void AmdOrdering::update_degrees(int32_t me) {
  int32_t* const iw = iw_;
  const int32_t tag = tag_;
  const uint32_t n = static_cast<uint32_t>(n_);
  for (int32_t p = pme1_; p < pme2_; ++p) {
    const int32_t i = iw[p];
    const int32_t p1 = nd_[i].pe;
    const int32_t p2 = p1 + nd_[i].elen;
    int32_t pn = p1;
    uint32_t hash = 0;
    int32_t deg = 0;
    for (int32_t q = p1; q < p2; ++q) {
      const int32_t e = iw[q];
      const int32_t we = nd_[e].w;
      if (we == 0) continue;  // absorbed into p in build_element
      const int32_t dext = we - tag;
      if (dext > 0 || !aggressive_) {
        deg += dext;
        iw[pn++] = e;
        hash += static_cast<uint32_t>(e);
      } else {
        // L_e ⊆ L_p: aggressive absorption.
        link_[e] = me;
        nd_[e].w = 0;
        nd_[e].pe = kNone;
        nd_[e].len = 0;
      }
    }
    const int32_t kept_elements = pn - p1;
    const int32_t p3 = pn;
    const int32_t p4 = p1 + nd_[i].len;
    // Keeps the variables outside L_p (drops p, L_p, merged and mass-eliminated
    // variables and dense rows). Branch-free: which entries survive is unpredictable.
    for (int32_t q = p2; q < p4; ++q) {
      const int32_t j = iw[q];
      const int32_t nvj = nd_[j].nv;
      const int32_t keep = nvj > 0 ? -1 : 0;
      iw[pn] = j;
      pn -= keep;
      deg += nvj & keep;
      hash += static_cast<uint32_t>(j & keep);
    }
    if (kept_elements == 0 && pn == p3 && i < inner_) {
      // Only p is left next to i: i's row equals p's, eliminate it with p.
      const int32_t nvi = -nd_[i].nv;
      link_[i] = me;
      degme_ -= nvi;
      nvpiv_ += nvi;
      nel_ += nvi;
      nd_[i].nv = 0;
      nd_[i].elen = kMassElim;
      nd_[i].pe = kNone;
      nd_[i].len = 0;
    } else {
      nd_[i].degree = std::min(nd_[i].degree, deg);
      // p goes first in E_i; the displaced element moves behind the elements, the
      // displaced variable to the end. Room exists: i lost at least p (from A_i) or
      // an element of E_p.
      iw[pn] = iw[p3];
      iw[p3] = iw[p1];
      iw[p1] = me;
      nd_[i].len = pn - p1 + 1;
      nd_[i].elen = kept_elements + 1;
      if (i >= inner_) continue;  // a halo vertex is never merged: not hashed
      const int32_t h = static_cast<int32_t>(hash % n);
      nd_[i].prev = h;
      nd_[i].next = hhead_[h];
      hhead_[h] = i;
    }
  }
}

// Supervariable detection: variables of L_p with equal hash are compared list against
// list; a match is merged into the first (it is indistinguishable from now on).
void AmdOrdering::merge_supervariables() {
  const int32_t* const iw = iw_;
  for (int32_t p = pme1_; p < pme2_; ++p) {
    const int32_t i = iw[p];
    if (nd_[i].nv >= 0 || i >= inner_) continue;  // mass-eliminated, merged or halo
    const int32_t h = nd_[i].prev;
    int32_t a = hhead_[h];
    if (a == kNone) continue;
    hhead_[h] = kNone;
    for (; a != kNone && nd_[a].next != kNone; a = nd_[a].next) {
      const int32_t la = nd_[a].len;
      const int32_t ea = nd_[a].elen;
      const int32_t pa = nd_[a].pe;
      // Every list starts with p: compare from the second word on.
      for (int32_t q = pa + 1; q < pa + la; ++q) nd_[iw[q]].w = tag_;
      int32_t before = a;
      for (int32_t b = nd_[a].next; b != kNone;) {
        const int32_t after = nd_[b].next;
        bool same = nd_[b].len == la && nd_[b].elen == ea;
        for (int32_t q = nd_[b].pe + 1, end = nd_[b].pe + nd_[b].len; same && q < end; ++q) {
          same = nd_[iw[q]].w == tag_;
        }
        if (same) {
          nd_[a].nv += nd_[b].nv;  // both negative while in L_p
          nd_[b].nv = 0;
          nd_[b].elen = kMerged;
          link_[b] = a;
          nd_[b].pe = kNone;
          nd_[b].len = 0;
          nd_[before].next = after;
        } else {
          before = b;
        }
        b = after;
      }
      ++tag_;
    }
  }
}

// Completes (2), files the variables of L_p in the degree lists, and compacts L_p to its
// principal variables.
void AmdOrdering::finalize_degrees(int32_t me) {
  int32_t* const iw = iw_;
  const int32_t nleft = n_ - nel_;
  int32_t dst = pme1_;
  for (int32_t p = pme1_; p < pme2_; ++p) {
    const int32_t i = iw[p];
    const int32_t nvi = -nd_[i].nv;
    if (nvi <= 0) continue;
    const int32_t deg = std::min(nd_[i].degree + degme_ - nvi, nleft - nvi);
    if (i < inner_) {
      insert_in_degree_list(i, deg);
      if (deg < mindeg_) mindeg_ = deg;
    }
    nd_[i].degree = deg;
    nd_[i].nv = nvi;
    iw[dst++] = i;
  }
  nd_[me].nv = nvpiv_;
  nd_[me].degree = degme_;
  nd_[me].len = dst - pme1_;
  if (nd_[me].len == 0) {
    nd_[me].pe = kNone;
    nd_[me].w = 0;  // an empty element touches nothing; it is a root of the tree
  }
  if (pfree_ == pme2_) pfree_ = dst;  // L_p was appended: give back its tail
}

void AmdOrdering::eliminate() {
  while (nel_ < inner_) {
    if (tag_ >= tag_limit_) reset_tags();
    const int32_t me = select_pivot();
    nvpiv_ = nd_[me].nv;
    nel_ += nvpiv_;
    nd_[me].nv = -nvpiv_;  // p itself is dropped from every list it appears in

    build_element(me);
    set_differences();
    update_degrees(me);
    // Tags of this pivot's |L_e \ L_p| values are below tag_ + lemax + 1.
    lemax_ = std::max(lemax_, degme_);
    tag_ += lemax_ + 1;
    merge_supervariables();
    ++tag_;
    finalize_degrees(me);

    count_block(nvpiv_, int64_t{degme_} + ndense_);
  }
  // The dense rows close the ordering as one dense block.
  if (ndense_ > 0) count_block(ndense_, 0);
}

// Adds the columns of a pivot block to the predictions: f columns that share r rows below
// the block, so the k-th has r + f - k off-diagonal entries.
void AmdOrdering::count_block(int64_t f, int64_t r) {
  lnz_ += f * r + f * (f - 1) / 2;
  // Σ_{c=r+1}^{r+f} c², c counting the diagonal, expanded to avoid cancellation.
  const double fd = static_cast<double>(f), rd = static_cast<double>(r);
  flops_ += fd * rd * rd + rd * fd * (fd + 1.0) + fd * (fd + 1.0) * (2.0 * fd + 1.0) / 6.0;
}

// Postorders the assembly tree and writes the permutation: the elements in postorder,
// each standing for the block of variables it eliminated (its pivot, the variables merged
// into it, those mass-eliminated with it), then the dense rows.
void AmdOrdering::order(int32_t* perm) {
  const int32_t n = n_;
  int32_t* const first_child = head_;
  int32_t* const stack = hhead_;
  for (int32_t i = 0; i < n; ++i) first_child[i] = kNone;
  // Children in increasing index order.
  for (int32_t e = n - 1; e >= 0; --e) {
    if (nd_[e].elen == kElement && link_[e] != kNone) {
      const int32_t parent = link_[e];
      nd_[e].next = first_child[parent];
      first_child[parent] = e;
    }
  }
  // The child with the largest front goes last, next to its parent: that is the front
  // relaxed supernode amalgamation may merge with the parent, and it keeps the
  // multifrontal stack small.
  for (int32_t e = 0; e < n; ++e) {
    if (nd_[e].elen != kElement || first_child[e] == kNone) continue;
    int32_t big = kNone, big_prev = kNone, big_size = -1, prev = kNone, last = kNone;
    for (int32_t c = first_child[e]; c != kNone; prev = c, c = nd_[c].next) {
      const int32_t front = nd_[c].nv + nd_[c].degree;
      if (front > big_size) {
        big = c;
        big_prev = prev;
        big_size = front;
      }
      last = c;
    }
    if (big != last) {
      if (big_prev == kNone) {
        first_child[e] = nd_[big].next;
      } else {
        nd_[big_prev].next = nd_[big].next;
      }
      nd_[last].next = big;
      nd_[big].next = kNone;
    }
  }
  // Depth-first postorder. The elimination is over, so the degree-list and tag fields are
  // free: nd_[e].w becomes the first position of e's block.
  int32_t k = 0;
  for (int32_t root = 0; root < n; ++root) {
    if (nd_[root].elen != kElement || link_[root] != kNone) continue;
    int32_t top = 0;
    stack[0] = root;
    while (top >= 0) {
      const int32_t e = stack[top];
      const int32_t c = first_child[e];
      if (c != kNone) {
        first_child[e] = nd_[c].next;
        stack[++top] = c;
      } else {
        --top;
        nd_[e].w = k;
        k += nd_[e].nv;
      }
    }
  }
  // Each variable's supervariable root is itself or the end of its chain of merges: a
  // pivot (now an element), or a variable mass-eliminated with the pivot link_[root].
  for (int32_t v = 0; v < n; ++v) {
    if (nd_[v].elen != kMerged) continue;
    int32_t root = v;
    while (nd_[root].elen == kMerged) root = link_[root];
    for (int32_t x = v; nd_[x].elen == kMerged;) {  // path compression
      const int32_t up = link_[x];
      link_[x] = root;
      x = up;
    }
  }
  // Within an element's block the pivot supervariable comes first, then the variables
  // mass-eliminated with it: exactly the elimination sequence, so the block is a clique
  // (one supernode) and the predicted nnz(L) is the ordering's. (Any other order within
  // the block has at most that fill.) Cursors: nd_[e].w for the pivot supervariable,
  // nd_[e].degree for the mass-eliminated ones, which start nv(e) - #mass-eliminated
  // positions into the block.
  for (int32_t e = 0; e < n; ++e) nd_[e].degree = 0;
  for (int32_t v = 0; v < inner_; ++v) {
    if (nd_[v].elen == kDense) continue;
    const int32_t root = nd_[v].elen == kMerged ? link_[v] : v;
    if (nd_[root].elen == kMassElim) ++nd_[link_[root]].degree;
  }
  for (int32_t e = 0; e < n; ++e) {
    if (nd_[e].elen == kElement) nd_[e].degree = nd_[e].w + nd_[e].nv - nd_[e].degree;
  }
  for (int32_t v = 0; v < inner_; ++v) {
    if (nd_[v].elen == kDense) continue;
    const int32_t root = nd_[v].elen == kMerged ? link_[v] : v;
    if (nd_[root].elen == kMassElim) {
      perm[nd_[link_[root]].degree++] = v;
    } else {
      perm[nd_[root].w++] = v;
    }
  }
  for (int32_t v = 0; v < n; ++v) {
    if (nd_[v].elen == kDense) perm[k++] = v;
  }
}

void AmdOrdering::fill_info(AmdInfo* info) const {
  info->n = n_;
  info->dense_rows = ndense_;
  info->nnz_L_estimate = lnz_ + n_;
  info->flops_estimate = flops_;
  info->compressions = compressions_;
}

// The workspace for a graph of nzfull entries over both triangles: the lists
// plus 20% elbow room, so that garbage collection is rare (anything from
// nnz + n + 1 on works, with more collections).
Status workspace_length(int32_t n, int64_t nzfull, int32_t* iwlen) {
  constexpr int64_t kMaxIndex = std::numeric_limits<int32_t>::max();
  const int64_t wanted = nzfull + nzfull / 5 + 2 * int64_t{n};
  const int64_t minimum = nzfull + n + 1;
  if (minimum > kMaxIndex) {
    return Status::Error(StatusCode::kOverflow,
                         "amd_order: the symmetric graph has too many entries for int32 "
                         "indices (" + std::to_string(nzfull) + ")");
  }
  *iwlen = static_cast<int32_t>(std::min(wanted, kMaxIndex));
  return Status::Ok();
}

}  // namespace

Status amd_order_graph(int32_t n, const int32_t* xadj, const int32_t* adj, std::vector<int32_t>* perm,
                       const AmdOptions& options) {
  return amd_order_graph_with_halo(n, n, xadj, adj, perm, options);
}

Status amd_order_graph_with_halo(int32_t n, int32_t inner, const int32_t* xadj, const int32_t* adj,
                                 std::vector<int32_t>* perm, const AmdOptions& options) {
  if (n < 0 || n >= (int32_t{1} << 30)) {
    return Status::Error(StatusCode::kInvalidArgument, "amd_order_graph: n must be in [0, 2^30)");
  }
  if (inner < 0 || inner > n) {
    return Status::Error(StatusCode::kInvalidArgument, "amd_order_graph: inner must be in [0, n]");
  }
  perm->resize(static_cast<size_t>(inner));
  if (inner == 0) return Status::Ok();
  std::unique_ptr<AmdOrdering::Node[]> nodes(new AmdOrdering::Node[static_cast<size_t>(n)]);
  std::unique_ptr<int32_t[]> heads(new int32_t[3 * static_cast<size_t>(n)]);
  AmdOrdering amd(n, nodes.get(), heads.get(), options, inner);
  int32_t iwlen = 0;
  GAB_RETURN_IF_ERROR(workspace_length(n, xadj[n], &iwlen));
  std::unique_ptr<int32_t[]> iw(new int32_t[static_cast<size_t>(iwlen)]);
  amd.build_graph(xadj[n], xadj, adj, iw.get(), iwlen, options);
  amd.eliminate();
  amd.order(perm->data());
  return Status::Ok();
}

Status amd_order(const CscMatrix& lower, std::vector<int32_t>* perm, const AmdOptions& options,
                 AmdInfo* info) {
  if (perm == nullptr) {
    return Status::Error(StatusCode::kInvalidArgument, "amd_order: perm is null");
  }
  const int32_t n = lower.ncols;
  if (n < 0 || lower.nrows != n) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "amd_order: matrix is not square (" + std::to_string(lower.nrows) +
                             " x " + std::to_string(lower.ncols) + ")");
  }
  if (lower.colptr.size() != static_cast<size_t>(n) + 1 || lower.colptr[0] != 0) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "amd_order: colptr must have n+1 entries starting at 0");
  }
  if (n >= (int32_t{1} << 30)) {
    return Status::Error(StatusCode::kOverflow, "amd_order: n must be below 2^30");
  }
  AmdInfo local_info;
  if (n == 0) {
    perm->clear();
    if (info != nullptr) *info = local_info;
    return Status::Ok();
  }
  // Workspace: allocated here, before the elimination, and never resized; left
  // uninitialised (every word is written before it is read).
  std::unique_ptr<AmdOrdering::Node[]> nodes(new AmdOrdering::Node[static_cast<size_t>(n)]);
  std::unique_ptr<int32_t[]> heads(new int32_t[3 * static_cast<size_t>(n)]);
  AmdOrdering amd(n, nodes.get(), heads.get(), options);
  int64_t nzfull = 0;
  GAB_RETURN_IF_ERROR(amd.count_entries(lower, &nzfull));
  int32_t iwlen = 0;
  GAB_RETURN_IF_ERROR(workspace_length(n, nzfull, &iwlen));
  std::unique_ptr<int32_t[]> iw(new int32_t[static_cast<size_t>(iwlen)]);
  amd.build_graph(lower, iw.get(), iwlen, options);
  perm->resize(static_cast<size_t>(n));
  amd.eliminate();
  amd.order(perm->data());
  amd.fill_info(&local_info);
  if (info != nullptr) *info = local_info;
  return Status::Ok();
}

}  // namespace gab
