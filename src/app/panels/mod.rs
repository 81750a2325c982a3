//! The panels, one per file: each a `*_ui` function that takes what it shows and returns commands.

pub(crate) mod banner;
pub(crate) mod bench_chart;
pub mod bench_panel;
pub mod canvas;
pub mod canvas_layout;
pub mod compare_image;
pub(crate) mod controls;
pub(crate) mod corners;
pub mod export;
pub(crate) mod file_menu;
pub mod gpu_view;
pub(crate) mod help;
pub(crate) mod image_size;
pub(crate) mod inspector;
pub mod lessons;
pub(crate) mod magnifier;
pub(crate) mod other_image;
pub(crate) mod paint;
pub(crate) mod path_window;
pub(crate) mod plots;
pub(crate) mod present;
pub(crate) mod samples_control;
pub(crate) mod space_view;
pub(crate) mod status;
pub(crate) mod tie_rule;
pub(crate) mod top_bar;
