module fwlib32-rs/examples/go

go 1.19
