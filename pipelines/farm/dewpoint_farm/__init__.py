"""Render-farm submission for dewpoint (pipelines/farm/submit, docs/farm.md)."""
