//! Morphologies: presets, row notation (top row first), voxel numbering
//! (bottom row first), neighbours, round trips and every error message.

use vsr::simulation::Shape;
use vsr::Error;

fn shape(spec: &str) -> Shape {
    match Shape::parse(spec) {
        Ok(s) => s,
        Err(e) => panic!("{spec} should parse: {e}"),
    }
}

fn error_message(spec: &str) -> String {
    match Shape::parse(spec) {
        Err(Error::Shape(m)) => m,
        other => panic!("{spec:?} should be a shape error, got {other:?}"),
    }
}

#[test]
fn presets_expand_to_the_paper_rows() {
    let cases = [
        ("biped-4x3", "1111-1111-1001", 4, 3, 10),
        ("comb-7x2", "1111111-1010101", 7, 2, 11),
        ("biped-6x4", "111111-111111-100011-100011", 6, 4, 18),
        ("comb-14x2", "11111111111111-10101010101010", 14, 2, 21),
        ("worm-5x1", "11111", 5, 1, 5),
        ("box-3x2", "111-111", 3, 2, 6),
    ];
    for (name, rows, w, h, n) in cases {
        let s = shape(name);
        assert_eq!(s.to_rows(), rows, "{name}");
        assert_eq!(
            (s.width(), s.height(), s.voxel_count()),
            (w, h, n),
            "{name}"
        );
        assert_eq!(s, shape(rows), "{name} equals its rows");
    }
}

#[test]
fn biped_voxels_are_numbered_bottom_row_first() {
    let s = shape("biped-4x3");
    let want: Vec<(usize, usize)> = vec![
        (0, 0),
        (3, 0),
        (0, 1),
        (1, 1),
        (2, 1),
        (3, 1),
        (0, 2),
        (1, 2),
        (2, 2),
        (3, 2),
    ];
    assert_eq!(s.voxels(), want.as_slice());
    for (i, &(x, y)) in want.iter().enumerate() {
        assert_eq!(s.index_of(x, y), Some(i));
    }
    assert_eq!(s.index_of(1, 0), None, "gap between the legs");
    assert_eq!(s.index_of(4, 0), None, "outside");
}

#[test]
fn is_filled_reads_bottom_up_and_is_false_outside() {
    let s = shape("biped-4x3");
    assert!(s.is_filled(0, 0) && s.is_filled(3, 0));
    assert!(!s.is_filled(1, 0) && !s.is_filled(2, 0));
    assert!(s.is_filled(1, 2));
    assert!(!s.is_filled(-1, 0) && !s.is_filled(0, -1));
    assert!(!s.is_filled(4, 1) && !s.is_filled(0, 3));
}

#[test]
fn biped_neighbours_are_up_right_down_left() {
    let s = shape("biped-4x3");
    assert_eq!(s.neighbours(0), [Some(2), None, None, None]);
    assert_eq!(s.neighbours(1), [Some(5), None, None, None]);
    assert_eq!(s.neighbours(3), [Some(7), Some(4), None, Some(2)]);
    assert_eq!(s.neighbours(2), [Some(6), Some(3), Some(0), None]);
    assert_eq!(s.neighbours(9), [None, None, Some(5), Some(8)]);
    assert_eq!(s.neighbours(10), [None; 4], "not a voxel index");
}

#[test]
fn comb_teeth_hang_from_the_top_row() {
    let s = shape("comb-7x2");
    // Bottom row: teeth at x = 0, 2, 4, 6 are voxels 0..3; the top row is 4..10.
    assert_eq!(&s.voxels()[..4], &[(0, 0), (2, 0), (4, 0), (6, 0)]);
    assert_eq!(s.neighbours(1), [Some(6), None, None, None]);
    assert_eq!(s.neighbours(4), [None, Some(5), Some(0), None]);
    assert_eq!(s.neighbours(5), [None, Some(6), None, Some(4)]);
    assert_eq!(s.neighbours(10), [None, None, Some(3), Some(9)]);
}

#[test]
fn rows_round_trip_through_parse_display_and_serde() {
    for rows in [
        "1",
        "10-11",
        "0110-1111-1001",
        "111111-111111-100011-100011",
    ] {
        let s = shape(rows);
        assert_eq!(s.to_rows(), rows);
        assert_eq!(s.to_string(), rows);
        let json = serde_json::to_string(&s).expect("serializes");
        assert_eq!(json, format!("\"{rows}\""));
        let back: Shape = serde_json::from_str(&json).expect("deserializes");
        assert_eq!(back, s);
    }
}

#[test]
fn deserializing_a_bad_shape_fails_with_its_message() {
    let err = serde_json::from_str::<Shape>("\"101\"").expect_err("disconnected");
    assert!(err.to_string().contains("2 separate pieces"), "{err}");
}

#[test]
fn whitespace_around_the_spec_and_rows_is_ignored() {
    assert_eq!(shape("  biped-4x3\n"), shape("biped-4x3"));
    assert_eq!(shape(" 11 - 01 ").to_rows(), "11-01");
}

#[test]
fn empty_shapes_have_no_voxels() {
    for spec in ["", "   ", "0", "000-000", "-"] {
        assert_eq!(error_message(spec), "the shape has no voxels", "{spec:?}");
    }
}

#[test]
fn ragged_rows_name_both_lengths() {
    assert_eq!(
        error_message("1111-11111"),
        "row 2 has 5 cells, row 1 has 4"
    );
    assert_eq!(error_message("11-11-1"), "row 3 has 1 cells, row 1 has 2");
}

#[test]
fn bad_characters_name_row_and_column() {
    assert_eq!(
        error_message("1111-11x1"),
        "row 2 has 'x' at column 3; use 1 for a voxel and 0 for an empty cell"
    );
    assert!(error_message("1#").starts_with("row 1 has '#' at column 2;"));
}

#[test]
fn disconnected_shapes_count_their_pieces() {
    let m = error_message("101");
    assert!(m.starts_with("the shape is in 2 separate pieces"), "{m}");
    let m = error_message("10-01");
    assert!(
        m.contains("2 separate pieces") && m.contains("diagonal"),
        "{m}"
    );
    assert!(error_message("10101-00000-10001").contains("5 separate pieces"));
}

#[test]
fn size_limits_are_enforced() {
    assert_eq!(
        error_message("box-21x20"),
        "the shape has 420 voxels; at most 400 are allowed"
    );
    assert_eq!(shape("box-20x20").voxel_count(), 400);
    assert_eq!(
        error_message("worm-101x1"),
        "the grid is 101 cells wide; at most 100 are allowed"
    );
    assert_eq!(
        error_message(&"1".repeat(101)),
        "the grid is 101 cells wide; at most 100 are allowed"
    );
    assert_eq!(
        error_message(&vec!["1"; 101].join("-")),
        "the grid is 101 cells tall; at most 100 are allowed"
    );
    assert_eq!(shape("worm-100x1").voxel_count(), 100);
    // A huge size is refused before anything is allocated.
    assert!(error_message("box-99999999x99999999").contains("at most 100"));
}

#[test]
fn worm_and_box_sizes_must_be_whole_and_positive() {
    assert_eq!(
        error_message("worm-0x3"),
        "'worm-0x3': width and height must be at least 1"
    );
    assert!(error_message("box-3x0").contains("at least 1"));
    for spec in ["worm-3", "box-x2", "worm-2.5x1", "box--1x2", "worm-ax2"] {
        assert!(
            error_message(spec).contains("expected a size WxH"),
            "{spec}"
        );
    }
}

#[test]
fn unknown_presets_list_what_is_accepted() {
    for spec in ["biped", "biped-4x4", "snake-3x1"] {
        let m = error_message(spec);
        assert!(m.starts_with(&format!("unknown preset '{spec}'")), "{m}");
        assert!(m.contains("biped-4x3, comb-7x2") && m.contains("1111-1111-1001"));
    }
}
