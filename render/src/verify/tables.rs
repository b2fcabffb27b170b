//! Markdown tables (placeholder, filled by the table writer).
