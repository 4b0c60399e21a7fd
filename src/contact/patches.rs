//! Contact patches: 4-connected clusters of contacting pixels on a periodic grid.

/// The number of 4-connected clusters of `true` pixels in a periodic `nx` × `ny`
/// grid (row-major): a cluster that leaves one edge and comes back at the
/// opposite one is one patch.
pub fn count_patches(contact: &[bool], nx: usize, ny: usize) -> usize {
    debug_assert_eq!(contact.len(), nx * ny);
    let mut parent: Vec<u32> = (0..contact.len() as u32).collect();
    let find = |parent: &mut Vec<u32>, mut i: u32| {
        while parent[i as usize] != i {
            let up = parent[parent[i as usize] as usize];
            parent[i as usize] = up;
            i = up;
        }
        i
    };
    let union = |parent: &mut Vec<u32>, a: usize, b: usize| {
        let (ra, rb) = (find(parent, a as u32), find(parent, b as u32));
        if ra != rb {
            let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
            parent[hi as usize] = lo;
        }
    };
    for j in 0..ny {
        for i in 0..nx {
            let here = j * nx + i;
            if !contact[here] {
                continue;
            }
            // Right and down neighbours, wrapping (a 1-wide direction has none).
            if nx > 1 {
                let right = j * nx + (i + 1) % nx;
                if contact[right] {
                    union(&mut parent, here, right);
                }
            }
            if ny > 1 {
                let down = ((j + 1) % ny) * nx + i;
                if contact[down] {
                    union(&mut parent, here, down);
                }
            }
        }
    }
    (0..contact.len())
        .filter(|&i| contact[i] && find(&mut parent, i as u32) == i as u32)
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(rows: &[&str]) -> (Vec<bool>, usize, usize) {
        let ny = rows.len();
        let nx = rows[0].len();
        let cells = rows
            .iter()
            .flat_map(|r| r.chars().map(|c| c == '#'))
            .collect();
        (cells, nx, ny)
    }

    #[test]
    fn clusters_are_four_connected_and_periodic() {
        // Counted by hand: two diagonal pixels are two patches; a patch cut by
        // the right edge is one; one cut by both edges (the corners) is one.
        let cases: &[(&[&str], usize)] = &[
            (&["....", "....", "...."], 0),
            (&["#...", ".#..", "...."], 2),
            (&["##..", "##..", "...."], 1),
            (&["#..#", "....", "...."], 1),
            (&["#..#", "....", "#..#"], 1),
            (&[".#..", "....", ".#.."], 1),
            (&["#.#.", "....", "#.#."], 2),
            (&["####", "####", "####"], 1),
            (&["#.#.#"], 2),
        ];
        for (rows, want) in cases {
            let (cells, nx, ny) = grid(rows);
            assert_eq!(count_patches(&cells, nx, ny), *want, "{rows:?}");
        }
    }
}
