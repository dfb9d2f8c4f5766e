"""Post-processing from recorder (SQLite case) files only: tables, figures and reports."""
