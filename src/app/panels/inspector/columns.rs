//! How the inspector's table of per-vertex numbers fits its panel: the number columns go side
//! by side as long as they fit, else in tables one below the other (each with the vertex
//! names), so a number is never cut off at the panel's edge, whatever the text size.

/// How many number columns go in one table: the most (up to all of them) for which every
/// table of that many fits in `width` points. `name`: the vertex names' column; `columns`:
/// each number column's width; `spacing`: points between two columns. At least 1.
pub(crate) fn per_table(width: f32, name: f32, columns: &[f32], spacing: f32) -> usize {
    (1..=columns.len().max(1))
        .rev()
        .find(|&k| {
            columns
                .chunks(k)
                .all(|chunk| name + chunk.iter().map(|w| w + spacing).sum::<f32>() <= width)
        })
        .unwrap_or(1)
}

/// The width in points of `text` laid out on one line in the body style of `ui`.
pub(crate) fn text_width(ui: &egui::Ui, text: egui::RichText) -> f32 {
    egui::WidgetText::from(text)
        .into_galley(
            ui,
            Some(egui::TextWrapMode::Extend),
            f32::INFINITY,
            egui::TextStyle::Body,
        )
        .size()
        .x
}

#[cfg(test)]
mod tests {
    use super::per_table;

    #[test]
    fn columns_go_below_each_other_when_they_do_not_fit() {
        let cols = [60.0, 60.0, 60.0];
        // Room for all: one table.
        assert_eq!(per_table(300.0, 40.0, &cols, 8.0), 3);
        assert_eq!(per_table(244.0, 40.0, &cols, 8.0), 3);
        // One point short: two tables (two columns, then one).
        assert_eq!(per_table(243.0, 40.0, &cols, 8.0), 2);
        assert_eq!(per_table(176.0, 40.0, &cols, 8.0), 2);
        // Then one column a table; never none.
        assert_eq!(per_table(175.0, 40.0, &cols, 8.0), 1);
        assert_eq!(per_table(10.0, 40.0, &cols, 8.0), 1);
        assert_eq!(per_table(10.0, 40.0, &[], 8.0), 1);
    }
}
