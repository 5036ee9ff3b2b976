use super::*;

#[path = "../../../../tests/support/xlsx.rs"]
mod xlsx;
use xlsx::{xlsx, Cell};

const A: &str = "http://localhost:8080/#k1.AAAA";
const B: &str = "#k1.BBBB_-";
const C: &str = "k1.CCCC";

fn read_text(text: &str) -> Vec<Handin> {
    read(text.as_bytes()).unwrap()
}

fn summary(h: &[Handin]) -> Vec<(usize, usize, &str, Option<&str>)> {
    h.iter()
        .map(|h| (h.row, h.line, h.student.as_str(), h.link.as_deref()))
        .collect()
}

#[test]
fn links_one_a_line_as_kumiki_check_always_read_them() {
    let text = format!("# the class of 3b\n{A}\n\n{B}\n   \n{C}\n");
    assert_eq!(
        summary(&read_text(&text)),
        vec![
            (1, 2, "", Some(A)),
            (2, 4, "", Some(B)),
            (3, 6, "", Some(C)),
        ]
    );
}

#[test]
fn a_form_export_with_answers_over_several_lines_keeps_one_row_a_hand_in() {
    // Three form rows; the answers hold line breaks, commas and doubled quotes, as RFC 4180 writes
    // them. A reader that splits on line breaks makes five hand-ins of these, one of them named
    // `Six was best."`.
    let text = format!(
        "\u{feff}Timestamp,Your name,Link,Why?\r\n\
         2026/11/28 10:15:00 AM GMT+1,Ada,{A},\"Fewer robots\r\ncollide less, I think.\"\r\n\
         2026/11/28 10:16:00 AM GMT+1,Grace,{B},plain\r\n\
         2026/11/28 10:17:00 AM GMT+1,\"Hopper, Grace\",{C},\"I tried \"\"5\"\"\nand 6.\nSix was best.\"\r\n"
    );
    let h = read_text(&text);
    assert_eq!(
        summary(&h),
        vec![
            (1, 2, "Ada", Some(A)),
            (2, 4, "Grace", Some(B)),
            (3, 5, "Hopper, Grace", Some(C)),
        ]
    );
}

#[test]
fn semicolons_and_tabs_separate_cells_as_spreadsheets_write_them() {
    let semi = format!("Name;Link;Note\nAda;{A};a, b\nGrace;{B};c\n");
    assert_eq!(
        summary(&read_text(&semi)),
        vec![(1, 2, "Ada", Some(A)), (2, 3, "Grace", Some(B))]
    );
    let tabs = format!("Student\tHand-in\nAda Lovelace\t{A}\n");
    assert_eq!(
        summary(&read_text(&tabs)),
        vec![(1, 2, "Ada Lovelace", Some(A))]
    );
}

#[test]
fn utf16_and_windows_1252_exports_are_text_and_binary_is_refused_with_one_message() {
    // Excel's "Unicode text": UTF-16 little-endian with its mark, tab-separated.
    let text = format!("Name\tLink\r\nZoë\t{A}\r\n");
    let mut utf16 = vec![0xff, 0xfe];
    utf16.extend(text.encode_utf16().flat_map(u16::to_le_bytes));
    assert_eq!(
        summary(&read(&utf16).unwrap()),
        vec![(1, 2, "Zoë", Some(A))]
    );
    // An older spreadsheet's CSV: Windows-1252.
    let mut latin: Vec<u8> = b"Name,Link\nRen".to_vec();
    latin.push(0xe9); // é
    latin.extend(format!("e,{A}\n").as_bytes());
    assert_eq!(read(&latin).unwrap()[0].student, "Renée");
    for binary in [
        &b"%PDF-1.7\n\x00\x01\x02"[..],
        &[0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a, 0, 0][..],
        &b"PK\x03\x04 not really a workbook"[..],
    ] {
        assert_eq!(read(binary).unwrap_err().to_string(), NOT_HANDINS);
    }
}

#[test]
fn rows_without_a_link_keep_their_place_and_say_where_they_are() {
    let text = format!("Name,Link\nAda,{A}\nGrace,forgot it\nHopper,{B}\n");
    let h = read_text(&text);
    assert_eq!(h[1].row, 2);
    assert_eq!(h[1].link, None);
    assert_eq!(
        h[1].no_link(),
        "holds no Kumiki link (line 3 of the file): Grace,forgot it"
    );
    assert_eq!(
        h[2].row, 3,
        "the table numbers hand-ins, not the file's lines"
    );
}

#[test]
fn a_first_and_last_name_make_the_students_name() {
    let text = format!("First name,Last name,Email,Link\nAda,Lovelace,ada@example.org,{A}\n");
    assert_eq!(read_text(&text)[0].student, "Ada Lovelace");
    // No header: the first cell that is neither a time nor a link.
    let bare = format!("2026-11-28T10:15:00Z,{A},Grace\n");
    assert_eq!(read_text(&bare)[0].student, "Grace");
}

#[test]
fn a_workbook_is_read_from_its_first_sheet() {
    let bytes = xlsx(&[
        vec![
            Cell::Text("Timestamp"),
            Cell::Text("Name"),
            Cell::Text("Link"),
            Cell::Text("Answer"),
        ],
        vec![
            Cell::Number(46_354.43),
            Cell::Text("Ada"),
            Cell::Text(A),
            Cell::Text("Two lines,\nwith a comma."),
        ],
        vec![
            Cell::Number(46_354.5),
            Cell::Text("Grace <3"),
            Cell::Text(B),
        ],
        vec![Cell::Number(7.0), Cell::Text("Hopper")],
    ]);
    let h = read(&bytes).unwrap();
    assert_eq!(
        summary(&h),
        vec![
            (1, 2, "Ada", Some(A)),
            (2, 3, "Grace <3", Some(B)),
            (3, 4, "Hopper", None),
        ]
    );
    assert_eq!(h[2].text, "7,Hopper");
}

#[test]
fn links_are_found_inside_cells_but_not_inside_words() {
    assert_eq!(find_link(&format!("my link: {A}, thanks")), Some(A));
    assert_eq!(
        find_link("http://x/?embed#k1.Zz9-_ more"),
        Some("http://x/?embed#k1.Zz9-_")
    );
    assert_eq!(find_link("work1.5 k1. bk1.AAAA"), None);
}
