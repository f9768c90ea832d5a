"""`glint bench`: what each variant and each tier costs, and how far each is from its reference."""
