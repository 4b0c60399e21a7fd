//! Space-filling designs in the unit cube, each point computable from its index
//! alone (so that a shard, a resumed run or a remote worker needs no state and
//! memory does not grow with the number of samples).
//!
//! * Sobol′ (Gray-code order, Joe & Kuo direction numbers, up to
//!   [`MAX_DIMENSIONS`]) with a random digital shift drawn from the seed: a
//!   shifted (t, m, s)-net keeps the stratification of the unshifted one.
//! * The same Sobol′ points Owen-scrambled ([`sobol_owen`], hash-based nested
//!   uniform scrambling), for the uncertainty engines: each point is uniform on
//!   the cube, so estimates are unbiased.
//! * Latin hypercube: in each dimension the strata `0..N` are visited in the
//!   order of a seeded pseudo-random permutation (a Feistel network with cycle
//!   walking: a bijection of `0..N` evaluated at one index in O(1) memory), with
//!   a seeded jitter inside the stratum.
//! * Full factorial grid: `m` levels per dimension including both ends, the
//!   last variable varying fastest.

/// The most dimensions a Sobol′ point has here (direction numbers tabulated).
pub const MAX_DIMENSIONS: usize = 256;

/// Joe & Kuo (2008), `new-joe-kuo-6.21201`, dimensions 2 to 256: the degree `s`,
/// the coefficients `a` of the primitive polynomial and the initial direction
/// integers `m_1 … m_s`. Dimension 1 is the van der Corput sequence (all `m = 1`).
/// The rows are those SciPy ships (`scipy/stats/_sobol_direction_numbers.npz`, the
/// same file), checked by the points compared with SciPy's below.
#[rustfmt::skip]
const JOE_KUO: [(u32, u32, &[u32]); MAX_DIMENSIONS - 1] = [
    (1, 0, &[1]),
    (2, 1, &[1, 3]),
    (3, 1, &[1, 3, 1]),
    (3, 2, &[1, 1, 1]),
    (4, 1, &[1, 1, 3, 3]),
    (4, 4, &[1, 3, 5, 13]),
    (5, 2, &[1, 1, 5, 5, 17]),
    (5, 4, &[1, 1, 5, 5, 5]),
    (5, 7, &[1, 1, 7, 11, 19]),
    (5, 11, &[1, 1, 5, 1, 1]),
    (5, 13, &[1, 1, 1, 3, 11]),
    (5, 14, &[1, 3, 5, 5, 31]),
    (6, 1, &[1, 3, 3, 9, 7, 49]),
    (6, 13, &[1, 1, 1, 15, 21, 21]),
    (6, 16, &[1, 3, 1, 13, 27, 49]),
    (6, 19, &[1, 1, 1, 15, 7, 5]),
    (6, 22, &[1, 3, 1, 15, 13, 25]),
    (6, 25, &[1, 1, 5, 5, 19, 61]),
    (7, 1, &[1, 3, 7, 11, 23, 15, 103]),
    (7, 4, &[1, 3, 7, 13, 13, 15, 69]),
    (7, 7, &[1, 1, 3, 13, 7, 35, 63]),
    (7, 8, &[1, 3, 5, 9, 1, 25, 53]),
    (7, 14, &[1, 3, 1, 13, 9, 35, 107]),
    (7, 19, &[1, 3, 1, 5, 27, 61, 31]),
    (7, 21, &[1, 1, 5, 11, 19, 41, 61]),
    (7, 28, &[1, 3, 5, 3, 3, 13, 69]),
    (7, 31, &[1, 1, 7, 13, 1, 19, 1]),
    (7, 32, &[1, 3, 7, 5, 13, 19, 59]),
    (7, 37, &[1, 1, 3, 9, 25, 29, 41]),
    (7, 41, &[1, 3, 5, 13, 23, 1, 55]),
    (7, 42, &[1, 3, 7, 3, 13, 59, 17]),
    (7, 50, &[1, 3, 1, 3, 5, 53, 69]),
    (7, 55, &[1, 1, 5, 5, 23, 33, 13]),
    (7, 56, &[1, 1, 7, 7, 1, 61, 123]),
    (7, 59, &[1, 1, 7, 9, 13, 61, 49]),
    (7, 62, &[1, 3, 3, 5, 3, 55, 33]),
    (8, 14, &[1, 3, 1, 15, 31, 13, 49, 245]),
    (8, 21, &[1, 3, 5, 15, 31, 59, 63, 97]),
    (8, 22, &[1, 3, 1, 11, 11, 11, 77, 249]),
    (8, 38, &[1, 3, 1, 11, 27, 43, 71, 9]),
    (8, 47, &[1, 1, 7, 15, 21, 11, 81, 45]),
    (8, 49, &[1, 3, 7, 3, 25, 31, 65, 79]),
    (8, 50, &[1, 3, 1, 1, 19, 11, 3, 205]),
    (8, 52, &[1, 1, 5, 9, 19, 21, 29, 157]),
    (8, 56, &[1, 3, 7, 11, 1, 33, 89, 185]),
    (8, 67, &[1, 3, 3, 3, 15, 9, 79, 71]),
    (8, 70, &[1, 3, 7, 11, 15, 39, 119, 27]),
    (8, 84, &[1, 1, 3, 1, 11, 31, 97, 225]),
    (8, 97, &[1, 1, 1, 3, 23, 43, 57, 177]),
    (8, 103, &[1, 3, 7, 7, 17, 17, 37, 71]),
    (8, 115, &[1, 3, 1, 5, 27, 63, 123, 213]),
    (8, 122, &[1, 1, 3, 5, 11, 43, 53, 133]),
    (9, 8, &[1, 3, 5, 5, 29, 17, 47, 173, 479]),
    (9, 13, &[1, 3, 3, 11, 3, 1, 109, 9, 69]),
    (9, 16, &[1, 1, 1, 5, 17, 39, 23, 5, 343]),
    (9, 22, &[1, 3, 1, 5, 25, 15, 31, 103, 499]),
    (9, 25, &[1, 1, 1, 11, 11, 17, 63, 105, 183]),
    (9, 44, &[1, 1, 5, 11, 9, 29, 97, 231, 363]),
    (9, 47, &[1, 1, 5, 15, 19, 45, 41, 7, 383]),
    (9, 52, &[1, 3, 7, 7, 31, 19, 83, 137, 221]),
    (9, 55, &[1, 1, 1, 3, 23, 15, 111, 223, 83]),
    (9, 59, &[1, 1, 5, 13, 31, 15, 55, 25, 161]),
    (9, 62, &[1, 1, 3, 13, 25, 47, 39, 87, 257]),
    (9, 67, &[1, 1, 1, 11, 21, 53, 125, 249, 293]),
    (9, 74, &[1, 1, 7, 11, 11, 7, 57, 79, 323]),
    (9, 81, &[1, 1, 5, 5, 17, 13, 81, 3, 131]),
    (9, 82, &[1, 1, 7, 13, 23, 7, 65, 251, 475]),
    (9, 87, &[1, 3, 5, 1, 9, 43, 3, 149, 11]),
    (9, 91, &[1, 1, 3, 13, 31, 13, 13, 255, 487]),
    (9, 94, &[1, 3, 3, 1, 5, 63, 89, 91, 127]),
    (9, 103, &[1, 1, 3, 3, 1, 19, 123, 127, 237]),
    (9, 104, &[1, 1, 5, 7, 23, 31, 37, 243, 289]),
    (9, 109, &[1, 1, 5, 11, 17, 53, 117, 183, 491]),
    (9, 122, &[1, 1, 1, 5, 1, 13, 13, 209, 345]),
    (9, 124, &[1, 1, 3, 15, 1, 57, 115, 7, 33]),
    (9, 137, &[1, 3, 1, 11, 7, 43, 81, 207, 175]),
    (9, 138, &[1, 3, 1, 1, 15, 27, 63, 255, 49]),
    (9, 143, &[1, 3, 5, 3, 27, 61, 105, 171, 305]),
    (9, 145, &[1, 1, 5, 3, 1, 3, 57, 249, 149]),
    (9, 152, &[1, 1, 3, 5, 5, 57, 15, 13, 159]),
    (9, 157, &[1, 1, 1, 11, 7, 11, 105, 141, 225]),
    (9, 167, &[1, 3, 3, 5, 27, 59, 121, 101, 271]),
    (9, 173, &[1, 3, 5, 9, 11, 49, 51, 59, 115]),
    (9, 176, &[1, 1, 7, 1, 23, 45, 125, 71, 419]),
    (9, 181, &[1, 1, 3, 5, 23, 5, 105, 109, 75]),
    (9, 182, &[1, 1, 7, 15, 7, 11, 67, 121, 453]),
    (9, 185, &[1, 3, 7, 3, 9, 13, 31, 27, 449]),
    (9, 191, &[1, 3, 1, 15, 19, 39, 39, 89, 15]),
    (9, 194, &[1, 1, 1, 1, 1, 33, 73, 145, 379]),
    (9, 199, &[1, 3, 1, 15, 15, 43, 29, 13, 483]),
    (9, 218, &[1, 1, 7, 3, 19, 27, 85, 131, 431]),
    (9, 220, &[1, 3, 3, 3, 5, 35, 23, 195, 349]),
    (9, 227, &[1, 3, 3, 7, 9, 27, 39, 59, 297]),
    (9, 229, &[1, 1, 3, 9, 11, 17, 13, 241, 157]),
    (9, 230, &[1, 3, 7, 15, 25, 57, 33, 189, 213]),
    (9, 234, &[1, 1, 7, 1, 9, 55, 73, 83, 217]),
    (9, 236, &[1, 3, 3, 13, 19, 27, 23, 113, 249]),
    (9, 241, &[1, 3, 5, 3, 23, 43, 3, 253, 479]),
    (9, 244, &[1, 1, 5, 5, 11, 5, 45, 117, 217]),
    (9, 253, &[1, 3, 3, 7, 29, 37, 33, 123, 147]),
    (10, 4, &[1, 3, 1, 15, 5, 5, 37, 227, 223, 459]),
    (10, 13, &[1, 1, 7, 5, 5, 39, 63, 255, 135, 487]),
    (10, 19, &[1, 3, 1, 7, 9, 7, 87, 249, 217, 599]),
    (10, 22, &[1, 1, 3, 13, 9, 47, 7, 225, 363, 247]),
    (10, 50, &[1, 3, 7, 13, 19, 13, 9, 67, 9, 737]),
    (10, 55, &[1, 3, 5, 5, 19, 59, 7, 41, 319, 677]),
    (10, 64, &[1, 1, 5, 3, 31, 63, 15, 43, 207, 789]),
    (10, 69, &[1, 1, 7, 9, 13, 39, 3, 47, 497, 169]),
    (10, 98, &[1, 3, 1, 7, 21, 17, 97, 19, 415, 905]),
    (10, 107, &[1, 3, 7, 1, 3, 31, 71, 111, 165, 127]),
    (10, 115, &[1, 1, 5, 11, 1, 61, 83, 119, 203, 847]),
    (10, 121, &[1, 3, 3, 13, 9, 61, 19, 97, 47, 35]),
    (10, 127, &[1, 1, 7, 7, 15, 29, 63, 95, 417, 469]),
    (10, 134, &[1, 3, 1, 9, 25, 9, 71, 57, 213, 385]),
    (10, 140, &[1, 3, 5, 13, 31, 47, 101, 57, 39, 341]),
    (10, 145, &[1, 1, 3, 3, 31, 57, 125, 173, 365, 551]),
    (10, 152, &[1, 3, 7, 1, 13, 57, 67, 157, 451, 707]),
    (10, 158, &[1, 1, 1, 7, 21, 13, 105, 89, 429, 965]),
    (10, 161, &[1, 1, 5, 9, 17, 51, 45, 119, 157, 141]),
    (10, 171, &[1, 3, 7, 7, 13, 45, 91, 9, 129, 741]),
    (10, 181, &[1, 3, 7, 1, 23, 57, 67, 141, 151, 571]),
    (10, 194, &[1, 1, 3, 11, 17, 47, 93, 107, 375, 157]),
    (10, 199, &[1, 3, 3, 5, 11, 21, 43, 51, 169, 915]),
    (10, 203, &[1, 1, 5, 3, 15, 55, 101, 67, 455, 625]),
    (10, 208, &[1, 3, 5, 9, 1, 23, 29, 47, 345, 595]),
    (10, 227, &[1, 3, 7, 7, 5, 49, 29, 155, 323, 589]),
    (10, 242, &[1, 3, 3, 7, 5, 41, 127, 61, 261, 717]),
    (10, 251, &[1, 3, 7, 7, 17, 23, 117, 67, 129, 1009]),
    (10, 253, &[1, 1, 3, 13, 11, 39, 21, 207, 123, 305]),
    (10, 265, &[1, 1, 3, 9, 29, 3, 95, 47, 231, 73]),
    (10, 266, &[1, 3, 1, 9, 1, 29, 117, 21, 441, 259]),
    (10, 274, &[1, 3, 1, 13, 21, 39, 125, 211, 439, 723]),
    (10, 283, &[1, 1, 7, 3, 17, 63, 115, 89, 49, 773]),
    (10, 289, &[1, 3, 7, 13, 11, 33, 101, 107, 63, 73]),
    (10, 295, &[1, 1, 5, 5, 13, 57, 63, 135, 437, 177]),
    (10, 301, &[1, 1, 3, 7, 27, 63, 93, 47, 417, 483]),
    (10, 316, &[1, 1, 3, 1, 23, 29, 1, 191, 49, 23]),
    (10, 319, &[1, 1, 3, 15, 25, 55, 9, 101, 219, 607]),
    (10, 324, &[1, 3, 1, 7, 7, 19, 51, 251, 393, 307]),
    (10, 346, &[1, 3, 3, 3, 25, 55, 17, 75, 337, 3]),
    (10, 352, &[1, 1, 1, 13, 25, 17, 65, 45, 479, 413]),
    (10, 361, &[1, 1, 7, 7, 27, 49, 99, 161, 213, 727]),
    (10, 367, &[1, 3, 5, 1, 23, 5, 43, 41, 251, 857]),
    (10, 382, &[1, 3, 3, 7, 11, 61, 39, 87, 383, 835]),
    (10, 395, &[1, 1, 3, 15, 13, 7, 29, 7, 505, 923]),
    (10, 398, &[1, 3, 7, 1, 5, 31, 47, 157, 445, 501]),
    (10, 400, &[1, 1, 3, 7, 1, 43, 9, 147, 115, 605]),
    (10, 412, &[1, 3, 3, 13, 5, 1, 119, 211, 455, 1001]),
    (10, 419, &[1, 1, 3, 5, 13, 19, 3, 243, 75, 843]),
    (10, 422, &[1, 3, 7, 7, 1, 19, 91, 249, 357, 589]),
    (10, 426, &[1, 1, 1, 9, 1, 25, 109, 197, 279, 411]),
    (10, 428, &[1, 3, 1, 15, 23, 57, 59, 135, 191, 75]),
    (10, 433, &[1, 1, 5, 15, 29, 21, 39, 253, 383, 349]),
    (10, 446, &[1, 3, 3, 5, 19, 45, 61, 151, 199, 981]),
    (10, 454, &[1, 3, 5, 13, 9, 61, 107, 141, 141, 1]),
    (10, 457, &[1, 3, 1, 11, 27, 25, 85, 105, 309, 979]),
    (10, 472, &[1, 3, 3, 11, 19, 7, 115, 223, 349, 43]),
    (10, 493, &[1, 1, 7, 9, 21, 39, 123, 21, 275, 927]),
    (10, 505, &[1, 1, 7, 13, 15, 41, 47, 243, 303, 437]),
    (10, 508, &[1, 1, 1, 7, 7, 3, 15, 99, 409, 719]),
    (11, 2, &[1, 3, 3, 15, 27, 49, 113, 123, 113, 67, 469]),
    (11, 11, &[1, 3, 7, 11, 3, 23, 87, 169, 119, 483, 199]),
    (11, 21, &[1, 1, 5, 15, 7, 17, 109, 229, 179, 213, 741]),
    (11, 22, &[1, 1, 5, 13, 11, 17, 25, 135, 403, 557, 1433]),
    (11, 35, &[1, 3, 1, 1, 1, 61, 67, 215, 189, 945, 1243]),
    (11, 49, &[1, 1, 7, 13, 17, 33, 9, 221, 429, 217, 1679]),
    (11, 50, &[1, 1, 3, 11, 27, 3, 15, 93, 93, 865, 1049]),
    (11, 56, &[1, 3, 7, 7, 25, 41, 121, 35, 373, 379, 1547]),
    (11, 61, &[1, 3, 3, 9, 11, 35, 45, 205, 241, 9, 59]),
    (11, 70, &[1, 3, 1, 7, 3, 51, 7, 177, 53, 975, 89]),
    (11, 74, &[1, 1, 3, 5, 27, 1, 113, 231, 299, 759, 861]),
    (11, 79, &[1, 3, 3, 15, 25, 29, 5, 255, 139, 891, 2031]),
    (11, 84, &[1, 3, 1, 1, 13, 9, 109, 193, 419, 95, 17]),
    (11, 88, &[1, 1, 7, 9, 3, 7, 29, 41, 135, 839, 867]),
    (11, 103, &[1, 1, 7, 9, 25, 49, 123, 217, 113, 909, 215]),
    (11, 104, &[1, 1, 7, 3, 23, 15, 43, 133, 217, 327, 901]),
    (11, 112, &[1, 1, 3, 3, 13, 53, 63, 123, 477, 711, 1387]),
    (11, 115, &[1, 1, 3, 15, 7, 29, 75, 119, 181, 957, 247]),
    (11, 117, &[1, 1, 1, 11, 27, 25, 109, 151, 267, 99, 1461]),
    (11, 122, &[1, 3, 7, 15, 5, 5, 53, 145, 11, 725, 1501]),
    (11, 134, &[1, 3, 7, 1, 9, 43, 71, 229, 157, 607, 1835]),
    (11, 137, &[1, 3, 3, 13, 25, 1, 5, 27, 471, 349, 127]),
    (11, 146, &[1, 1, 1, 1, 23, 37, 9, 221, 269, 897, 1685]),
    (11, 148, &[1, 1, 3, 3, 31, 29, 51, 19, 311, 553, 1969]),
    (11, 157, &[1, 3, 7, 5, 5, 55, 17, 39, 475, 671, 1529]),
    (11, 158, &[1, 1, 7, 1, 1, 35, 47, 27, 437, 395, 1635]),
    (11, 162, &[1, 1, 7, 3, 13, 23, 43, 135, 327, 139, 389]),
    (11, 164, &[1, 3, 7, 3, 9, 25, 91, 25, 429, 219, 513]),
    (11, 168, &[1, 1, 3, 5, 13, 29, 119, 201, 277, 157, 2043]),
    (11, 173, &[1, 3, 5, 3, 29, 57, 13, 17, 167, 739, 1031]),
    (11, 185, &[1, 3, 3, 5, 29, 21, 95, 27, 255, 679, 1531]),
    (11, 186, &[1, 3, 7, 15, 9, 5, 21, 71, 61, 961, 1201]),
    (11, 191, &[1, 3, 5, 13, 15, 57, 33, 93, 459, 867, 223]),
    (11, 193, &[1, 1, 1, 15, 17, 43, 127, 191, 67, 177, 1073]),
    (11, 199, &[1, 1, 1, 15, 23, 7, 21, 199, 75, 293, 1611]),
    (11, 213, &[1, 3, 7, 13, 15, 39, 21, 149, 65, 741, 319]),
    (11, 214, &[1, 3, 7, 11, 23, 13, 101, 89, 277, 519, 711]),
    (11, 220, &[1, 3, 7, 15, 19, 27, 85, 203, 441, 97, 1895]),
    (11, 227, &[1, 3, 1, 3, 29, 25, 21, 155, 11, 191, 197]),
    (11, 236, &[1, 1, 7, 5, 27, 11, 81, 101, 457, 675, 1687]),
    (11, 242, &[1, 3, 1, 5, 25, 5, 65, 193, 41, 567, 781]),
    (11, 251, &[1, 3, 1, 5, 11, 15, 113, 77, 411, 695, 1111]),
    (11, 256, &[1, 1, 3, 9, 11, 53, 119, 171, 55, 297, 509]),
    (11, 259, &[1, 1, 1, 1, 11, 39, 113, 139, 165, 347, 595]),
    (11, 265, &[1, 3, 7, 11, 9, 17, 101, 13, 81, 325, 1733]),
    (11, 266, &[1, 3, 1, 1, 21, 43, 115, 9, 113, 907, 645]),
    (11, 276, &[1, 1, 7, 3, 9, 25, 117, 197, 159, 471, 475]),
    (11, 292, &[1, 3, 1, 9, 11, 21, 57, 207, 485, 613, 1661]),
    (11, 304, &[1, 1, 7, 7, 27, 55, 49, 223, 89, 85, 1523]),
    (11, 310, &[1, 1, 5, 3, 19, 41, 45, 51, 447, 299, 1355]),
    (11, 316, &[1, 3, 1, 13, 1, 33, 117, 143, 313, 187, 1073]),
    (11, 319, &[1, 1, 7, 7, 5, 11, 65, 97, 377, 377, 1501]),
    (11, 322, &[1, 3, 1, 1, 21, 35, 95, 65, 99, 23, 1239]),
    (11, 328, &[1, 1, 5, 9, 3, 37, 95, 167, 115, 425, 867]),
    (11, 334, &[1, 3, 3, 13, 1, 37, 27, 189, 81, 679, 773]),
    (11, 339, &[1, 1, 3, 11, 1, 61, 99, 233, 429, 969, 49]),
    (11, 341, &[1, 1, 1, 7, 25, 63, 99, 165, 245, 793, 1143]),
    (11, 345, &[1, 1, 5, 11, 11, 43, 55, 65, 71, 283, 273]),
    (11, 346, &[1, 1, 5, 5, 9, 3, 101, 251, 355, 379, 1611]),
    (11, 362, &[1, 1, 1, 15, 21, 63, 85, 99, 49, 749, 1335]),
    (11, 367, &[1, 1, 5, 13, 27, 9, 121, 43, 255, 715, 289]),
    (11, 372, &[1, 3, 1, 5, 27, 19, 17, 223, 77, 571, 1415]),
    (11, 375, &[1, 1, 5, 3, 13, 59, 125, 251, 195, 551, 1737]),
    (11, 376, &[1, 3, 3, 15, 13, 27, 49, 105, 389, 971, 755]),
    (11, 381, &[1, 3, 5, 15, 23, 43, 35, 107, 447, 763, 253]),
    (11, 385, &[1, 3, 5, 11, 21, 3, 17, 39, 497, 407, 611]),
    (11, 388, &[1, 1, 7, 13, 15, 31, 113, 17, 23, 507, 1995]),
    (11, 392, &[1, 1, 7, 15, 3, 15, 31, 153, 423, 79, 503]),
    (11, 409, &[1, 1, 7, 9, 19, 25, 23, 171, 505, 923, 1989]),
    (11, 415, &[1, 1, 5, 9, 21, 27, 121, 223, 133, 87, 697]),
    (11, 416, &[1, 1, 5, 5, 9, 19, 107, 99, 319, 765, 1461]),
    (11, 421, &[1, 1, 3, 3, 19, 25, 3, 101, 171, 729, 187]),
    (11, 428, &[1, 1, 3, 1, 13, 23, 85, 93, 291, 209, 37]),
    (11, 431, &[1, 1, 1, 15, 25, 25, 77, 253, 333, 947, 1073]),
    (11, 434, &[1, 1, 3, 9, 17, 29, 55, 47, 255, 305, 2037]),
    (11, 439, &[1, 3, 3, 9, 29, 63, 9, 103, 489, 939, 1523]),
    (11, 446, &[1, 3, 7, 15, 7, 31, 89, 175, 369, 339, 595]),
    (11, 451, &[1, 3, 7, 13, 25, 5, 71, 207, 251, 367, 665]),
    (11, 453, &[1, 3, 3, 3, 21, 25, 75, 35, 31, 321, 1603]),
    (11, 457, &[1, 1, 1, 9, 11, 1, 65, 5, 11, 329, 535]),
    (11, 458, &[1, 1, 5, 3, 19, 13, 17, 43, 379, 485, 383]),
    (11, 471, &[1, 3, 5, 13, 13, 9, 85, 147, 489, 787, 1133]),
    (11, 475, &[1, 3, 1, 1, 5, 51, 37, 129, 195, 297, 1783]),
    (11, 478, &[1, 1, 3, 15, 19, 57, 59, 181, 455, 697, 2033]),
    (11, 484, &[1, 3, 7, 1, 27, 9, 65, 145, 325, 189, 201]),
    (11, 493, &[1, 3, 1, 15, 31, 23, 19, 5, 485, 581, 539]),
    (11, 494, &[1, 1, 7, 13, 11, 15, 65, 83, 185, 847, 831]),
    (11, 499, &[1, 3, 5, 7, 7, 55, 73, 15, 303, 511, 1905]),
    (11, 502, &[1, 3, 5, 9, 7, 21, 45, 15, 397, 385, 597]),
    (11, 517, &[1, 3, 7, 3, 23, 13, 73, 221, 511, 883, 1265]),
    (11, 518, &[1, 1, 3, 11, 1, 51, 73, 185, 33, 975, 1441]),
    (11, 524, &[1, 3, 3, 9, 19, 59, 21, 39, 339, 37, 143]),
    (11, 527, &[1, 1, 7, 1, 31, 33, 19, 167, 117, 635, 639]),
    (11, 555, &[1, 1, 1, 3, 5, 13, 59, 83, 355, 349, 1967]),
    (11, 560, &[1, 1, 1, 5, 19, 3, 53, 133, 97, 863, 983]),
];

/// The 32 direction numbers `V_k = m_k 2^{32-k}` of every dimension, computed once.
fn direction_table() -> &'static [[u32; 32]] {
    static TABLE: std::sync::OnceLock<Vec<[u32; 32]>> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| (0..MAX_DIMENSIONS).map(direction_numbers).collect())
}

/// The 32 direction numbers `V_k = m_k 2^{32-k}` of dimension `d` (0-based).
fn direction_numbers(d: usize) -> [u32; 32] {
    let mut v = [0u32; 32];
    if d == 0 {
        for (k, vk) in v.iter_mut().enumerate() {
            *vk = 1u32 << (31 - k);
        }
        return v;
    }
    let (s, a, m) = JOE_KUO[d - 1];
    let s = s as usize;
    for k in 0..s {
        v[k] = m[k] << (31 - k);
    }
    for k in s..32 {
        let mut x = v[k - s] ^ (v[k - s] >> s);
        for j in 1..s {
            if (a >> (s - 1 - j)) & 1 == 1 {
                x ^= v[k - j];
            }
        }
        v[k] = x;
    }
    v
}

/// The unscrambled Sobol′ point `index` (Gray-code order, the order of
/// `scipy.stats.qmc.Sobol(scramble=False)`) as 32-bit integers, one per dimension.
/// `index < 2^32`, `dims ≤ MAX_DIMENSIONS`.
pub fn sobol_bits(index: u64, dims: usize) -> Vec<u32> {
    let gray = index ^ (index >> 1);
    let table = direction_table();
    (0..dims.min(MAX_DIMENSIONS))
        .map(|d| {
            let v = &table[d];
            let mut x = 0u32;
            for (k, vk) in v.iter().enumerate() {
                if (gray >> k) & 1 == 1 {
                    x ^= vk;
                }
            }
            x
        })
        .collect()
}

/// splitmix64 (Steele, Lea & Flood 2014): a well-mixed 64-bit hash.
pub fn splitmix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A hash of (seed, stream, index): independent streams per purpose and dimension.
fn mix(seed: u64, stream: u64, index: u64) -> u64 {
    splitmix(splitmix(splitmix(seed) ^ stream.wrapping_mul(0xD6E8_FEB8_6659_FD93)) ^ index)
}

/// A uniform double in [0, 1) from 53 bits of a hash.
fn unit(bits: u64) -> f64 {
    (bits >> 11) as f64 / (1u64 << 53) as f64
}

/// The digitally shifted Sobol′ point `index` in [0, 1)^dims.
pub fn sobol(index: u64, dims: usize, seed: u64) -> Vec<f64> {
    sobol_bits(index, dims)
        .into_iter()
        .enumerate()
        .map(|(d, x)| {
            let shift = (mix(seed, 1 + d as u64, 0) >> 32) as u32;
            (x ^ shift) as f64 / 4_294_967_296.0
        })
        .collect()
}

/// A nested uniform (Owen) scramble of the 32 binary digits of `x`: a hash on the
/// bit-reversed integer in which every bit depends only on the bits below it and
/// the seed (Laine & Karras 2011; Burley 2020, "Practical hash-based Owen
/// scrambling", JCGT 9(4), with his improved constants). Reversed back, digit `j`
/// after the binary point is permuted depending only on digits `1 … j−1`, as in
/// Owen's scrambling; for a fixed seed the map is a bijection of the 32-bit integers.
pub fn owen_scramble(x: u32, seed: u32) -> u32 {
    let mut x = x.reverse_bits();
    x ^= x.wrapping_mul(0x3d20_adea);
    x = x.wrapping_add(seed);
    x = x.wrapping_mul((seed >> 16) | 1);
    x ^= x.wrapping_mul(0x0552_6c56);
    x ^= x.wrapping_mul(0x53a2_2864);
    x.reverse_bits()
}

/// The Owen-scrambled Sobol′ point `index` in the open cube (0, 1)^dims: each
/// dimension's 32 digits scrambled by [`owen_scramble`] with a seed drawn from
/// (`seed`, dimension), the digits below 2⁻³² filled by a hash of (`seed`,
/// dimension, `index`). Scrambling keeps the (t, m, s)-net property of the first
/// 2^m points and makes each point uniform on the cube, so sample means are
/// unbiased and their error can be estimated from replicates. Computed from the
/// index alone; `index < 2^32`, `dims ≤ MAX_DIMENSIONS`.
pub fn sobol_owen(index: u64, dims: usize, seed: u64) -> Vec<f64> {
    sobol_bits(index, dims)
        .into_iter()
        .enumerate()
        .map(|(d, x)| {
            let key = (mix(seed, 7000 + d as u64, 0) >> 32) as u32;
            let low = unit(mix(seed, 9000 + d as u64, index));
            let u = (owen_scramble(x, key) as f64 + low) / 4_294_967_296.0;
            u.clamp(f64::MIN_POSITIVE, 1.0 - f64::EPSILON / 2.0)
        })
        .collect()
}

/// A seeded bijection of `0..n`, evaluated at `i < n`: a four-round balanced
/// Feistel network on the smallest even bit width covering `n`, cycle-walked
/// back into `0..n` (each walk step stays inside the permutation's cycle, so
/// the restriction is again a bijection).
pub fn permute(i: u64, n: u64, key: u64) -> u64 {
    debug_assert!(i < n);
    if n <= 1 {
        return 0;
    }
    let bits = 64 - (n - 1).leading_zeros();
    let half = bits.div_ceil(2);
    let mask = (1u64 << half) - 1;
    let mut x = i;
    loop {
        let (mut l, mut r) = (x >> half, x & mask);
        for round in 0..4u64 {
            let f = splitmix(key ^ r ^ round.wrapping_mul(0xA24B_AED4_963E_E407)) & mask;
            (l, r) = (r, l ^ f);
        }
        x = (l << half) | r;
        if x < n {
            return x;
        }
    }
}

/// The Latin-hypercube point `index` of `n` in [0, 1)^dims.
pub fn latin_hypercube(index: u64, n: u64, dims: usize, seed: u64) -> Vec<f64> {
    (0..dims)
        .map(|d| {
            let stream = 1000 + d as u64;
            let stratum = permute(index, n, mix(seed, stream, u64::MAX));
            let jitter = unit(mix(seed, stream, index));
            ((stratum as f64 + jitter) / n as f64).min(1.0 - f64::EPSILON / 2.0)
        })
        .collect()
}

/// `m` with `m^dims == n`, if there is one.
pub fn grid_levels(n: u64, dims: usize) -> Option<u64> {
    if dims == 0 {
        return None;
    }
    let guess = (n as f64).powf(1.0 / dims as f64).round() as u64;
    (guess.saturating_sub(1)..=guess + 1)
        .find(|&m| m >= 1 && (m as u128).checked_pow(dims as u32) == Some(n as u128))
}

/// The grid point `index` with `levels` per dimension: level `j` at `j/(levels-1)`
/// (a single level sits at the centre), the last dimension varying fastest.
pub fn grid(index: u64, levels: u64, dims: usize) -> Vec<f64> {
    let mut out = vec![0.0; dims];
    let mut rest = index;
    for slot in out.iter_mut().rev() {
        let j = rest % levels;
        rest /= levels;
        *slot = if levels == 1 {
            0.5
        } else {
            j as f64 / (levels - 1) as f64
        };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permutation_is_a_bijection() {
        for n in [1u64, 2, 3, 7, 64, 1000, 1025] {
            for key in [0u64, 1, 0xDEAD_BEEF] {
                let mut seen = vec![false; n as usize];
                for i in 0..n {
                    let p = permute(i, n, key);
                    assert!(p < n);
                    assert!(!seen[p as usize], "n {n} key {key}: {p} twice");
                    seen[p as usize] = true;
                }
            }
        }
    }

    #[test]
    fn grid_levels_only_for_exact_powers() {
        assert_eq!(grid_levels(1000, 3), Some(10));
        assert_eq!(grid_levels(999, 3), None);
        assert_eq!(grid_levels(1, 5), Some(1));
        assert_eq!(grid_levels(7, 1), Some(7));
        assert_eq!(grid_levels(1 << 40, 2), Some(1 << 20));
    }

    #[test]
    fn grid_covers_both_ends() {
        assert_eq!(grid(0, 3, 2), vec![0.0, 0.0]);
        assert_eq!(grid(1, 3, 2), vec![0.0, 0.5]);
        assert_eq!(grid(8, 3, 2), vec![1.0, 1.0]);
        assert_eq!(grid(0, 1, 2), vec![0.5, 0.5]);
    }
}

#[cfg(test)]
mod scipy_reference {
    use super::*;

    /// `scipy.stats.qmc.Sobol(d=10, scramble=False, bits=32)` (SciPy 1.17.1), advanced with
    /// `fast_forward(i)` and `random(1)`, times 2^32: an independent implementation with the
    /// same Joe & Kuo direction numbers. Large indices exercise the high direction numbers.
    const TABLE: [(u64, [u32; 10]); 5] = [
        (
            7,
            [
                536870912, 2684354560, 1610612736, 536870912, 536870912, 1610612736, 2684354560,
                2684354560, 2684354560, 3758096384,
            ],
        ),
        (
            1000,
            [
                943718400, 415236096, 2227175424, 2906652672, 1203765248, 3896508416, 197132288,
                3862953984, 2151677952, 297795584,
            ],
        ),
        (
            123457,
            [
                2261286912, 2932375552, 3467149312, 4081549312, 2874114048, 3020455936, 926973952,
                4140597248, 886734848, 3217195008,
            ],
        ),
        (
            1048593,
            [
                2550142976, 2147514368, 1442347008, 4250712064, 1840314368, 2608920576, 3256813568,
                1307809792, 1574639616, 734492672,
            ],
        ),
        (
            4000000000,
            [
                4029081, 1592571143, 3353822765, 712656571, 3960376661, 1314381763, 3643749407,
                1872652665, 1479076361, 3616889337,
            ],
        ),
    ];

    #[test]
    fn sobol_matches_scipy() {
        for (i, want) in TABLE {
            assert_eq!(sobol_bits(i, 10), want.to_vec(), "index {i}");
        }
    }

    /// `scipy.stats.qmc.Sobol(d=256, scramble=False, bits=32)` (SciPy 1.17.1), advanced
    /// with `fast_forward(i)` and `random(1)`, times 2^32, at the 0-based dimensions
    /// `DIMS`: the rows beyond the first ten (Joe & Kuo up to dimension 256).
    const DIMS: [usize; 12] = [10, 11, 20, 31, 50, 63, 64, 100, 127, 128, 200, 255];
    #[rustfmt::skip]
    const HIGH: [(u64, [u32; 12]); 5] = [
        (7, [2684354560, 536870912, 3758096384, 3758096384, 3758096384, 1610612736, 536870912, 1610612736, 1610612736, 3758096384, 3758096384, 536870912]),
        (1000, [364904448, 1094713344, 2243952640, 624951296, 1514143744, 1916796928, 557842432, 3300917248, 2336227328, 3829399552, 3233808384, 1069547520]),
        (123457, [4291133440, 1207664640, 2654699520, 2472640512, 3265167360, 1941929984, 2148958208, 135561216, 341934080, 2924249088, 4180246528, 4239163392]),
        (1048593, [3094689792, 2927564800, 573233152, 3860518912, 1045616640, 2943485952, 3554121728, 1255032832, 3416102912, 1170593792, 715507712, 2867460096]),
        (4000000000, [1271123557, 3690252653, 2722880469, 3430693387, 1190163441, 1332632889, 4086664041, 2733308063, 3435811143, 2619950935, 3247600475, 1567106179]),
    ];

    #[test]
    fn high_dimensions_match_scipy() {
        for (i, want) in HIGH {
            let bits = sobol_bits(i, MAX_DIMENSIONS);
            let got: Vec<u32> = DIMS.iter().map(|&d| bits[d]).collect();
            assert_eq!(got, want.to_vec(), "index {i}");
        }
    }

    #[test]
    fn owen_scrambled_points_stratify_and_differ_by_seed() {
        // The scramble is a bijection of the digits that keeps the net: the first 2^k
        // points still put one point in each interval [j/2^k, (j+1)/2^k) of every axis.
        let k = 7;
        for seed in [0u64, 11] {
            for d in [0, 1, 9, 63, 200] {
                let mut seen = vec![false; 1 << k];
                for i in 0..(1u64 << k) {
                    let u = sobol_owen(i, MAX_DIMENSIONS, seed)[d];
                    assert!(u > 0.0 && u < 1.0);
                    let j = (u * (1 << k) as f64) as usize;
                    assert!(!seen[j], "seed {seed} dim {d}: stratum {j} twice");
                    seen[j] = true;
                }
            }
        }
        assert_ne!(sobol_owen(5, 3, 0), sobol_owen(5, 3, 1));
        assert_eq!(sobol_owen(5, 3, 1), sobol_owen(5, 3, 1));
    }

    #[test]
    fn owen_scramble_is_a_bijection_keeping_leading_digits_nested() {
        // Two integers agreeing in their top j digits are mapped to integers agreeing
        // in their top j digits (the nested property of Owen's scrambling).
        let seed = 0x1234_5678;
        for x in [0u32, 1, 0x8000_0000, 0xDEAD_BEEF, 0x0F0F_0F0F] {
            for j in 1..32 {
                let y = x ^ (1u32 << (31 - j));
                let (a, b) = (owen_scramble(x, seed), owen_scramble(y, seed));
                assert_eq!(a >> (32 - j), b >> (32 - j), "x {x:#x} j {j}");
                assert_ne!(a, b);
            }
        }
    }

    #[test]
    fn first_power_of_two_points_stratify_every_axis() {
        // A (t, m, s)-net property that the digital shift keeps: the first 2^k points
        // put exactly one point in each interval [j/2^k, (j+1)/2^k) of every axis.
        for seed in [0u64, 7] {
            let k = 8;
            for d in 0..MAX_DIMENSIONS {
                let mut seen = vec![false; 1 << k];
                for i in 0..(1u64 << k) {
                    let u = sobol(i, MAX_DIMENSIONS, seed)[d];
                    let j = (u * (1 << k) as f64) as usize;
                    assert!(!seen[j], "seed {seed} dim {d}: stratum {j} twice");
                    seen[j] = true;
                }
            }
        }
    }

    #[test]
    fn latin_hypercube_hits_each_stratum_once() {
        for n in [1u64, 5, 100, 257] {
            for d in 0..3 {
                let mut seen = vec![false; n as usize];
                for i in 0..n {
                    let u = latin_hypercube(i, n, 3, 42)[d];
                    assert!((0.0..1.0).contains(&u));
                    let j = (u * n as f64) as usize;
                    assert!(!seen[j]);
                    seen[j] = true;
                }
            }
        }
    }
}
