"""What a notebook shows of an AovSet and a Partition (`_repr_html_`): the explorer's
drawing with its state and edge ids and a table of the AOVs, and the partition's
findings as a table; names and expressions escaped. Values worked by hand."""

import lpe


def test_an_aov_set_draws_itself_with_a_table_of_its_aovs():
    # `C<RD>L` by hand: start, after C, after C RD, after C RD L (accepting `d`); the
    # AOV names are escaped in the table and in the accepting state's title.
    s = lpe.AovSet({"d<x>": "C<RD>L"})
    html = s._repr_html_()
    head = '<div class="lpe-aovset"><p>1 AOVs (renderman), 4 states, 3 edges</p><svg'
    assert html.startswith(head)
    for state in ("s0", "s1", "s2", "s3"):
        assert f'<ellipse id="{state}"' in html
    for edge in ("e0-1", "e1-2", "e2-3"):
        assert f'<path id="{edge}"' in html
    assert "<td>d&lt;x&gt;</td><td><code>C&lt;RD&gt;L</code></td><td>s3</td>" in html
    assert "<title>s3: d&lt;x&gt;</title>" in html
    assert "d<x>" not in html


def test_an_aov_set_too_large_to_draw_says_so():
    # C.*<RD>.{8}L remembers the last nine scatter vertices: 2^9 + 2 = 514 states.
    html = lpe.AovSet({"far": "C.*<RD>.{8}L"})._repr_html_()
    assert "514 states" in html
    assert "<svg" not in html
    assert "too large to draw" in html
    assert "<td>far</td>" in html


def test_a_partition_shows_its_findings_as_a_table():
    # As test_partition_gap_with_its_remainder: C<RD>L and C.*L overlap on C RD L and
    # leave C O uncovered. Planted fault, checked by hand: the gap's row labelled
    # `outside` (`python/src/analysis.rs`) fails this test.
    p = lpe.partition({"a": "C<RD>L", "b": "C.*L"})
    html = p._repr_html_()
    assert "partition of <code>C.*[&lt;L.&gt;O]</code>: 2 findings" in html
    assert "<tr><td>overlap</td><td>a, b</td><td><code>C RD1 L</code></td></tr>" in html
    assert "<tr><td>gap</td><td></td><td><code>C O</code></td></tr>" in html
    assert "remainder: <code>" in html
    clean = lpe.partition(["directDiffuse", "indirectDiffuse", "subsurface", "directSpecular",
                           "indirectSpecular", "transmissive", "emissive"])._repr_html_()
    assert ": clean</p>" in clean and "<table>" not in clean
