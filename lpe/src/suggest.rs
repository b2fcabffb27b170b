//! "Did you mean" suggestions, shared by every dialect's error messages: the names
//! nearest to a misspelt one by edit distance (macro, prefix and built-in AOV names).

/// Levenshtein distance, ignoring ASCII case: for "did you mean" suggestions.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().map(|c| c.to_ascii_lowercase()).collect();
    let b: Vec<char> = b.chars().map(|c| c.to_ascii_lowercase()).collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

/// The candidates nearest to `name`, best first, at most `n`.
pub fn nearest<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
    n: usize,
) -> Vec<&'a str> {
    let mut scored: Vec<(usize, &str)> = candidates
        .into_iter()
        .map(|c| (edit_distance(name, c), c))
        .collect();
    scored.sort();
    scored.dedup_by(|a, b| a.1.eq_ignore_ascii_case(b.1));
    scored.into_iter().take(n).map(|(_, c)| c).collect()
}

/// The candidate nearest to `name` if it is at most `max_distance` edits away: a
/// suggestion worth making (a typo), not merely the least far of unrelated names.
pub fn close<'a>(
    name: &str,
    candidates: impl IntoIterator<Item = &'a str>,
    max_distance: usize,
) -> Option<&'a str> {
    nearest(name, candidates, 1)
        .into_iter()
        .find(|c| edit_distance(name, c) <= max_distance)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_is_levenshtein() {
        assert_eq!(edit_distance("holdout", "holdouts"), 1);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("ABC", "abc"), 0);
        assert_eq!(edit_distance("", "abc"), 3);
        // Deletions after the first character read the row above. Planted fault, seen
        // failing: `prev[j * 1]` for `prev[j + 1]` (8 and 3 here).
        assert_eq!(edit_distance("holdouts", "holdout"), 1);
        assert_eq!(edit_distance("cab", "c"), 2);
    }

    #[test]
    fn nearest_ranks_by_distance_and_keeps_n() {
        let names = ["diffuse_direct", "diffuse_indirect", "specular", "coat"];
        assert_eq!(nearest("difuse_direct", names, 1), ["diffuse_direct"]);
        assert_eq!(nearest("coats", names, 2), ["coat", "specular"]);
        assert!(nearest("x", [], 3).is_empty());
    }

    #[test]
    fn close_suggests_only_within_the_distance() {
        let names = ["karma", "arnold", "vray"];
        assert_eq!(close("karm", names, 2), Some("karma"));
        assert_eq!(close("arnlod", names, 2), Some("arnold"));
        assert_eq!(close("cycles", names, 2), None);
        assert_eq!(close("vary", names, 1), None);
    }
}
