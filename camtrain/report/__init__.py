"""Outputs: tables (CSV, JSON), the input echo, terminal report."""
